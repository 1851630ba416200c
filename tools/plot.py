#!/usr/bin/python3
"""Figures of an aggregated sweep (run by `fsweep plot DIR`).

Reads DIR/summary.csv, DIR/progress_summary.csv and DIR/best.csv (written by
`fsweep aggregate`, src/report/aggregate.hpp) and writes to --out (default DIR/plots):

  progress.png           explored area vs distance: mean line and q05-q95 band per configuration
                         (Rappaport 2016, Figure 4), one panel per map class
  metrics.png            median with q05-q95 bars of distance, energy, coverage and distance to
                         the final coverage, per configuration, grouped by map class
  heatmap_<wi>_<wj>.png  weight searches (at least three values in each of at least two of
                         strategy.w1..w4): the objective's median over each pair of weights, the
                         best value over the other weights and columns
  search<k>_<wa>_<wb>.png  exact weight searches (DIR/search_heatmaps.csv, written by `fsweep
                         run` for a search of mode "all"): per search k and pair of weights with
                         at least two values each, the best objective of any weight vector with
                         those two values
  search<k>_gap.png      exact weight searches of mode "best" (DIR/search_anytime.csv): the best
                         objective found and the certified bound of the optimum over time, the
                         gap between them shaded; drawn for a stopped search too (a directory
                         with no summary.csv then gets this figure only)

Each configuration is named by what tells it apart from the others drawn: its strategy label
(with the parameters that differ within the label), then the planner, robot and sim columns
that differ, a preset standing for its numbers (energy=mei2006, not every per-metre and per-turn
cost), prefixes such as `robot.` left out. Per map class the best --top configurations by
best.csv's ranking are drawn (the title says so when there are more), one colour per name in
every panel. Legends sit below the axes, never on them.

--layout-json FILE writes, per figure, the bounding boxes (in pixels) matplotlib gives the
figure, its axes, their titles, labels and tick labels, the figure's title and the legend, so a
test can check that nothing is cut off or covered (tests/plots/check_plot_layout.py); each text
says what it is (role: title, xlabel, ylabel, xtick, ytick).

Needs Python 3 and matplotlib only; output is deterministic (no timestamps).
"""

import argparse
import csv
import itertools
import json
import math
import os
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402
from matplotlib.ticker import FuncFormatter  # noqa: E402

WEIGHTS = ["strategy.w1", "strategy.w2", "strategy.w3", "strategy.w4"]
METRICS = [
    ("distance_m", "distance (m)"),
    ("energy", "energy"),
    ("coverage", "coverage"),
    ("distance_to_final_coverage_m", "distance to final coverage (m)"),
]
# Objectives where larger is better; the others are minimised (as in aggregate.hpp).
MAXIMISED = {"area_per_metre"}
SAVE = {"dpi": 120, "metadata": {"Software": None}}
# Columns whose value names others (src/report/config_names.hpp): they stand for what they determine.
NAMING = ("map_class", "strategy_label", "planner")
LEGEND_FONT = 8
WRAP = 48  # characters per legend or tick-label line

LAYOUT = {}  # file name -> bounding boxes, for --layout-json


def read_csv(path):
    """Header and rows (dicts) of a CSV file; exits with a message naming a missing file."""
    if not os.path.exists(path):
        sys.exit(f"plot.py: {path}: not found (run `fsweep aggregate` first)")
    with open(path, newline="", encoding="utf-8") as f:
        reader = csv.DictReader(f)
        return reader.fieldnames or [], list(reader)


def number(text):
    """A CSV cell as a float, NaN when empty or not a number."""
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def compact(v):
    """A short label for a heat-map cell: 3 significant digits, k/M for thousands/millions."""
    for scale, suffix in ((1e6, "M"), (1e3, "k")):
        if abs(v) >= scale:
            return f"{v / scale:.3g}{suffix}"
    return f"{v:.3g}"


def short_name(column):
    """A column's name for labels: without the strategy./robot./planner./sim. prefix, a preset as
    its model ('robot.energy.preset' -> 'energy')."""
    if column.endswith(".preset"):
        column = column[:-len(".preset")]
    for prefix in ("strategy.", "robot.", "planner.", "sim."):
        if column.startswith(prefix):
            return column[len(prefix):]
    return column


def naming(column):
    return column in NAMING or column.endswith(".preset")


def determines(by, of, rows):
    """True when, over rows, the value of column `by` determines that of column `of`."""
    seen = {}
    for r in rows:
        if seen.setdefault(r[by], r[of]) != r[of]:
            return False
    return True


def telling_columns(columns, rows):
    """The columns that tell rows apart: more than one value, less those a naming column
    (map_class, strategy_label, planner, *.preset) determines (as src/report/config_names.hpp)."""
    varying = [c for c in columns if len({r[c] for r in rows}) > 1]
    names = [c for c in varying if naming(c)]
    return [c for c in varying if naming(c) or not any(determines(k, c, rows) for k in names)]


def strategy_names(side, rows):
    """Per row, its strategy's name: the label, with the side columns that differ within it."""
    label = "strategy_label" if "strategy_label" in side else ("strategy" if "strategy" in side else None)
    if label is None:
        return ["" for _ in rows]
    values = {}
    for r in rows:
        for c in side:
            values.setdefault((r[label], c), set()).add(r[c])
    out = []
    for r in rows:
        parts = [r[label]]
        parts += [f"{short_name(c)}={r[c]}" for c in side
                  if c != label and r[c] != "" and len(values[(r[label], c)]) > 1]
        out.append(" ".join(parts))
    return out


def config_labels(header, rows):
    """config_id -> its name without the map class (file comment), config_id -> its map class."""
    config_cols = header[header.index("config_id") + 1:header.index("n")]
    side = [c for c in config_cols if c in ("strategy_label", "strategy") or c.startswith("strategy.")]
    other = [c for c in config_cols if c not in side]
    names = strategy_names(side, rows)
    variant = [c for c in telling_columns(other, rows) if c != "map_class"]  # the panels are the classes
    labels, classes = {}, {}
    for r, name in zip(rows, names):
        parts = [name] if name else []
        parts += [f"{short_name(c)}={r[c]}" for c in variant if r[c] != ""]
        labels[r["config_id"]] = " · ".join(parts) or f"config {r['config_id']}"
        classes[r["config_id"]] = r.get("map_class", "")
    return labels, classes


def objective_of(best_header):
    median_col = next((c for c in best_header if c.endswith(".median")), "objective.median")
    return median_col[:-len(".median")]


def shown_configs(best_rows, classes, top):
    """Per map class (in best.csv's order of first appearance), its best `top` config_ids; and
    whether some class has more."""
    per_class = {}
    for r in best_rows:
        per_class.setdefault(classes.get(r["config_id"], ""), []).append(r["config_id"])
    cut = any(len(ids) > top for ids in per_class.values())
    return {c: ids[:top] for c, ids in per_class.items()}, per_class, cut


def selection_note(per_class, shown, objective, cut):
    counts = sorted({len(ids) for ids in per_class.values()})
    total = "/".join(str(n) for n in counts)
    per = " per map class" if len(per_class) > 1 else ""
    if cut:
        top = max(len(ids) for ids in shown.values())
        return f"the best {top} of {total} configurations{per} by median {objective}"
    return f"{total} configurations{per}, by median {objective}"


def colours_for(names):
    """A colour (and dash pattern beyond 20) per name, in order."""
    palette = plt.get_cmap("tab10" if len(names) <= 10 else "tab20")
    n = 10 if len(names) <= 10 else 20
    dashes = ["-", "--", ":", "-."]
    return {name: (palette(k % n), dashes[(k // n) % len(dashes)]) for k, name in enumerate(names)}


def wrapped(text, width=WRAP):
    return "\n".join(textwrap.wrap(text, width, break_on_hyphens=False)) or text


def legend_below(fig, legend_ax, handles, labels, width_in):
    """The legend in its own axes under the panels (so it can never cover one), `width_in` wide."""
    legend_ax.axis("off")
    if not handles:
        return None
    longest = max(max(len(line) for line in lab.split("\n")) for lab in labels)
    ncol = max(1, min(len(labels), int(width_in / (longest * 0.068 + 0.55))))
    return legend_ax.legend(handles, labels, loc="upper center", ncol=ncol, fontsize=LEGEND_FONT, frameon=False,
                            borderaxespad=0.0, handlelength=2.2)


def legend_height_in(labels, width_in):
    """The height (inches) a legend of `labels` takes in a figure `width_in` wide (legend_below)."""
    if not labels:
        return 0.1
    longest = max(max(len(line) for line in lab.split("\n")) for lab in labels)
    ncol = max(1, min(len(labels), int(width_in / (longest * 0.068 + 0.55))))
    lines_per_entry = max(lab.count("\n") + 1 for lab in labels)
    rows = math.ceil(len(labels) / ncol)
    return 0.2 + rows * lines_per_entry * 0.17


def drawn_tick_labels(axis):
    """The tick labels matplotlib draws: those of the ticks within the axis' view interval."""
    lo, hi = sorted(axis.get_view_interval())
    slack = 1e-9 * max(1.0, abs(hi - lo))
    return [t.label1 for t in axis.get_major_ticks() if lo - slack <= t.get_loc() <= hi + slack and t.label1.get_visible()]


def record_layout(name, fig):
    """The bounding boxes of `fig`'s parts, for --layout-json."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()

    def box(artist):
        b = artist.get_window_extent(renderer)
        return [b.x0, b.y0, b.x1, b.y1]

    entry = {"figure": [0, 0, fig.bbox.width, fig.bbox.height], "axes": [], "texts": [], "legends": []}
    for ax in fig.axes:
        if not ax.axison:  # the legend's own row
            for leg in [ax.get_legend()] if ax.get_legend() else []:
                entry["legends"].append(box(leg))
            continue
        entry["axes"].append(box(ax.patch))
        texts = ([("title", ax.title), ("xlabel", ax.xaxis.label), ("ylabel", ax.yaxis.label)]
                 + [("xtick", t) for t in drawn_tick_labels(ax.xaxis)]
                 + [("ytick", t) for t in drawn_tick_labels(ax.yaxis)])
        entry["texts"] += [{"text": t.get_text(), "box": box(t), "role": role} for role, t in texts
                           if t.get_text() and t.get_visible()]
        if ax.get_legend():
            entry["legends"].append(box(ax.get_legend()))
    if fig._suptitle is not None:
        entry["texts"].append({"text": fig._suptitle.get_text(), "box": box(fig._suptitle), "suptitle": True})
    LAYOUT[name] = entry


def save(fig, out, name):
    record_layout(name, fig)
    fig.savefig(os.path.join(out, name), **SAVE)
    plt.close(fig)
    return name


def panel_grid(count):
    cols = 1 if count == 1 else 2 if count in (2, 4) else 3
    return cols, math.ceil(count / cols)


def progress_panel(ax, cls, ids, curves, labels, style):
    """One map class's curves: each configuration's mean explored area and q05-q95 band."""
    ns = set()
    for config_id in ids:
        rows = sorted(curves.get(config_id, []), key=lambda r: number(r["distance_m"]))
        if not rows:
            continue
        ns.add(rows[0]["n"])
        d = [number(r["distance_m"]) for r in rows]
        colour, dash = style[labels[config_id]]
        ax.fill_between(d, [number(r["explored_area_m2.q05"]) for r in rows],
                        [number(r["explored_area_m2.q95"]) for r in rows], color=colour, alpha=0.15, linewidth=0)
        ax.plot(d, [number(r["explored_area_m2.mean"]) for r in rows], color=colour, linestyle=dash, linewidth=1.5,
                marker="o" if len(d) == 1 else None)
    runs = f"n = {ns.pop()} runs each" if len(ns) == 1 else ""
    ax.set_title(wrapped(f"{cls} ({runs})" if cls and runs else cls or runs, 60), fontsize=10)
    ax.set_xlabel("distance travelled (m)", fontsize=9)
    ax.set_ylabel("explored area (m²)", fontsize=9)
    ax.tick_params(labelsize=8)
    ax.grid(True, alpha=0.3)
    ax.set_xlim(left=0)
    ax.set_ylim(bottom=0)


def plot_progress(progress_rows, shown, labels, note, out):
    """A panel per map class; one legend below them all when every class draws the same few
    configurations (one colour each everywhere), else a legend below each panel."""
    curves = {}
    for r in progress_rows:
        curves.setdefault(r["config_id"], []).append(r)
    classes = list(shown)
    names = {cls: [labels[i] for i in shown[cls]] for cls in classes}
    union = list(dict.fromkeys(n for cls in classes for n in names[cls]))
    shared = len(union) <= 10
    styles = {cls: colours_for(union if shared else names[cls]) for cls in classes}
    if not classes:  # a sweep of weight searches only: no runs of its own
        classes, shown, names, styles = [""], {"": []}, {"": []}, {"": {}}
    cols, rows_n = panel_grid(len(classes))
    width = max(7.0, 4.6 * cols + 1.0)
    if shared:
        legend_rows = [legend_height_in([wrapped(n) for n in union], width)]
        ratios = [3.6] * rows_n + legend_rows
    else:
        legend_rows = [max(legend_height_in([wrapped(n, 40) for n in names[c]], width / cols)
                           for c in classes[r * cols:(r + 1) * cols]) for r in range(rows_n)]
        ratios = [x for r in range(rows_n) for x in (3.6, legend_rows[r])]
    fig = plt.figure(figsize=(width, sum(ratios) + 0.9), layout="constrained")
    grid = fig.add_gridspec(len(ratios), cols, height_ratios=ratios)
    for k, cls in enumerate(classes):
        row, col = (k // cols, k % cols) if shared else (2 * (k // cols), k % cols)
        progress_panel(fig.add_subplot(grid[row, col]), cls, shown[cls], curves, labels, styles[cls])
        if not shared:
            handles = [Line2D([], [], color=styles[cls][n][0], linestyle=styles[cls][n][1], linewidth=2)
                       for n in names[cls]]
            legend_below(fig, fig.add_subplot(grid[row + 1, col]), handles, [wrapped(n, 40) for n in names[cls]],
                         width / cols)
    if shared:
        handles = [Line2D([], [], color=styles[classes[0]][n][0], linestyle=styles[classes[0]][n][1], linewidth=2)
                   for n in union]
        legend_below(fig, fig.add_subplot(grid[rows_n, :]), handles, [wrapped(n) for n in union], width)
    fig.suptitle(wrapped("Explored area vs distance: mean and q05–q95 band; " + note, 90), fontsize=11)
    return save(fig, out, "progress.png")


def plot_metrics(summary_header, summary_rows, shown, labels, note, out):
    by_id = {r["config_id"]: r for r in summary_rows}
    metrics = [(m, t) for m, t in METRICS if f"{m}.median" in summary_header]
    several = len(shown) > 1
    ids = [i for ids in shown.values() for i in ids]
    names = [wrapped((f"{cls} · " if several else "") + labels[i]) for cls, cids in shown.items() for i in cids]
    units = {r.get("robot.energy.unit", "") for r in summary_rows}
    colours = colours_for(list(shown))
    cols = max(1, len(metrics))  # one row of panels sharing the names on the left
    lines = sum(n.count("\n") + 1 for n in names)
    height = max(2.8, 0.16 * lines + 0.1 * len(ids) + 1.6)
    label_width = min(WRAP, max((len(line) for n in names for line in n.split("\n")), default=10)) * 0.068 + 0.4
    fig, axes = plt.subplots(1, cols, figsize=(label_width + 2.6 * cols, height), squeeze=False,
                             layout="constrained")
    y = list(range(len(ids)))
    for k, (metric, title) in enumerate(metrics):
        ax = axes[0][k]
        med = [number(by_id[i][f"{metric}.median"]) for i in ids]
        lo = [max(0.0, m - number(by_id[i][f"{metric}.q05"])) for m, i in zip(med, ids)]
        hi = [max(0.0, number(by_id[i][f"{metric}.q95"]) - m) for m, i in zip(med, ids)]
        bar_colours = [colours[cls][0] for cls, cids in shown.items() for _ in cids]
        ax.barh(y, med, xerr=[lo, hi], color=bar_colours, alpha=0.8, error_kw={"ecolor": "black", "capsize": 2})
        ax.set_yticks(y)
        ax.set_yticklabels(names if k == 0 else [], fontsize=7)
        ax.invert_yaxis()  # best first, at the top
        if metric == "energy" and units - {""}:
            title = f"energy ({', '.join(sorted(units - {''}))})"
        ax.set_title(title, fontsize=10)
        ax.tick_params(axis="x", labelsize=8)
        ax.grid(True, axis="x", alpha=0.3)
    fig.suptitle(wrapped("Median per configuration, bars q05–q95; " + note
                         + ("; colour: map class" if several else ""), 100), fontsize=11)
    return save(fig, out, "metrics.png")


def plot_heatmaps(summary_header, summary_rows, best_header, best_rows, out):
    """heatmap_<wi>_<wj>.png for every pair of varying weights; returns the files written."""
    # A weight grid: at least three values of a weight (two weight vectors make no map).
    varying = [w for w in WEIGHTS if w in summary_header
               and len({r[w] for r in summary_rows if r[w] != ""}) > 2]
    median_col = next((c for c in best_header if c.endswith(".median")), None)
    if len(varying) < 2 or median_col is None:
        return []
    objective = median_col[:-len(".median")]
    better = max if objective in MAXIMISED else min
    weights = {r["config_id"]: r for r in summary_rows}
    config_cols = summary_header[summary_header.index("config_id") + 1:summary_header.index("n")]
    written = []
    for wi, wj in itertools.combinations(varying, 2):
        # Other config columns varying among these configurations: a cell keeps the best of them.
        rows = [weights[r["config_id"]] for r in best_rows if weights[r["config_id"]][wi] != ""
                and weights[r["config_id"]][wj] != ""]
        varied = [c for c in config_cols if c not in (wi, wj) and len({r[c] for r in rows}) > 1]
        others = ", ".join(short_name(c) for c in varied[:3]) + (", ..." if len(varied) > 3 else "")
        cells = {}
        for r in best_rows:
            s = weights[r["config_id"]]
            x, yv, v = number(s[wi]), number(s[wj]), number(r[median_col])
            if math.isnan(x) or math.isnan(yv) or math.isnan(v):
                continue
            cells[(x, yv)] = better(cells[(x, yv)], v) if (x, yv) in cells else v
        if not cells:
            continue
        xs = sorted({x for x, _ in cells})
        ys = sorted({yv for _, yv in cells})
        grid = [[cells.get((x, yv), math.nan) for x in xs] for yv in ys]
        fig, ax = plt.subplots(figsize=(max(6.0, 0.42 * len(xs) + 2.5), max(4.5, 0.36 * len(ys) + 1.8)),
                               layout="constrained")
        cmap = plt.get_cmap("viridis" if objective in MAXIMISED else "viridis_r").copy()
        cmap.set_bad("lightgrey")
        image = ax.imshow(grid, origin="lower", cmap=cmap, aspect="auto")
        value_ticks(ax, xs, ys)
        ax.set_xlabel(short_name(wi), fontsize=11)
        ax.set_ylabel(short_name(wj), fontsize=11)
        # Values are printed only where the cells are wide enough for them.
        if len(xs) <= 8 and len(ys) <= 12:
            for (x, yv), v in cells.items():
                ax.text(xs.index(x), ys.index(yv), compact(v), ha="center", va="center", fontsize=7, color="white",
                        bbox={"facecolor": "black", "alpha": 0.25, "pad": 1, "linewidth": 0})
        # The best cell (ties: smallest weights) framed in red.
        bx, by = min(cells, key=lambda c: (-cells[c] if objective in MAXIMISED else cells[c], c))
        ax.add_patch(Rectangle((xs.index(bx) - 0.5, ys.index(by) - 0.5), 1, 1, fill=False, edgecolor="red",
                               linewidth=2.5))
        ax.set_title(wrapped(f"median {objective} ({'max' if better is max else 'min'} over {others}; best framed)"
                             if others else f"median {objective} (best framed)", 60), fontsize=10)
        fig.colorbar(image, ax=ax, label=f"median {objective}")
        written.append(save(fig, out, f"heatmap_{short_name(wi)}_{short_name(wj)}.png"))
    return written


def value_ticks(ax, xs, ys):
    """Tick labels of a heat map's cells: the values `xs`, `ys`, at most about 15 of each."""
    step_x = max(1, math.ceil(len(xs) / 15))
    step_y = max(1, math.ceil(len(ys) / 15))
    ax.set_xticks(range(0, len(xs), step_x))
    ax.set_xticklabels([f"{xs[k]:g}" for k in range(0, len(xs), step_x)], fontsize=8)
    ax.set_yticks(range(0, len(ys), step_y))
    ax.set_yticklabels([f"{ys[k]:g}" for k in range(0, len(ys), step_y)], fontsize=8)


def plot_search_heatmaps(path, out):
    """search<k>_<wa>_<wb>.png from an exact search's search_heatmaps.csv; the files written."""
    if not os.path.exists(path):
        return []
    _, rows = read_csv(path)
    maps = {}
    for r in rows:
        key = (r["search_id"], r["weight_a"], r["weight_b"])
        maps.setdefault(key, {})[(number(r["value_a"]), number(r["value_b"]))] = number(r["best_objective"])
    written = []
    for (search, wa, wb), cells in maps.items():
        xs = sorted({x for x, _ in cells})
        ys = sorted({y for _, y in cells})
        if len(xs) < 2 or len(ys) < 2:
            continue
        grid = [[cells.get((x, y), math.nan) for x in xs] for y in ys]
        fig, ax = plt.subplots(figsize=(7.0, 5.5), layout="constrained")
        cmap = plt.get_cmap("viridis_r").copy()
        cmap.set_bad("lightgrey")
        image = ax.imshow(grid, origin="lower", cmap=cmap, aspect="auto")
        value_ticks(ax, xs, ys)
        finite = {c: v for c, v in cells.items() if not math.isnan(v)}
        if finite:  # the best cell (ties: smallest weights) framed in red
            bx, by = min(finite, key=lambda c: (finite[c], c))
            ax.add_patch(Rectangle((xs.index(bx) - 0.5, ys.index(by) - 0.5), 1, 1, fill=False, edgecolor="red",
                                   linewidth=2))
        ax.set_xlabel(wa, fontsize=11)
        ax.set_ylabel(wb, fontsize=11)
        ax.set_title(wrapped(f"exact search {search}: best objective over the other weights (best framed)", 60),
                     fontsize=10)
        fig.colorbar(image, ax=ax, label="best objective")
        written.append(save(fig, out, f"search{search}_{wa}_{wb}.png"))
    return written


def objective_label(directory):
    """The y-axis label of a search's objective, from DIR/manifest.json's "objective" (a runs.csv
    column: `distance_to_coverage_target_m` reads "distance to coverage target (m)"); "objective"
    when the manifest does not say."""
    try:
        with open(os.path.join(directory, "manifest.json"), encoding="utf-8") as f:
            manifest = json.load(f)
    except (OSError, ValueError):
        return "objective"
    name = manifest.get("objective") if isinstance(manifest, dict) else None
    if not isinstance(name, str) or not name:
        return "objective"
    for suffix, unit in (("_m2", " (m²)"), ("_m", " (m)"), ("_s", " (s)")):
        if name.endswith(suffix):
            return name[: -len(suffix)].replace("_", " ") + unit
    return name.replace("_", " ")


def thousands(ticks):
    """A tick formatter for `ticks`: thousands separated, with as many decimals as their spacing
    needs (so that close ticks read apart)."""
    steps = [b - a for a, b in zip(ticks, ticks[1:]) if b > a]
    decimals = 0
    while steps and decimals < 6 and abs(round(min(steps), decimals) - min(steps)) > 1e-9 * max(1.0, min(steps)):
        decimals += 1
    return lambda v, _: f"{v:,.{decimals}f}"


ANYTIME_COLUMNS = ("search_id", "elapsed_s", "status", "resolved_vectors", "vectors", "best", "bound",
                   "relative_gap")


def anytime_problem(path):
    """What makes search_anytime.csv at `path` no search curve to draw (None when nothing does), and
    its rows: every column there, every row whole, times and counts numbers and best and bound empty
    or numbers, all within +-1e300 (matplotlib cannot scale beyond)."""
    try:
        header, rows = read_csv(path)
    except (OSError, UnicodeDecodeError, csv.Error) as e:
        return f"cannot be read ({e})", []
    missing = [c for c in ANYTIME_COLUMNS if c not in header]
    if missing:
        return f"no column {', '.join(missing)}: not a search curve", []
    for line, r in enumerate(rows, start=2):
        if None in r or any(v is None for v in r.values()):
            return f"line {line} has {len(header)} fields expected, not as many", []
        if not r["search_id"].isdigit():  # it names the figure's file
            return f"line {line}: search_id {r['search_id']!r} is not a whole number", []
        for column in ("elapsed_s", "resolved_vectors", "vectors"):
            if not abs(number(r[column])) <= 1e300:  # NaN too
                return f"line {line}: {column} {r[column]!r} is not a number within 1e300", []
        for column in ("best", "bound"):
            v = number(r[column])
            if r[column] != "" and not (math.isfinite(v) and abs(v) <= 1e300):
                return f"line {line}: {column} {r[column]!r} is neither empty nor a number within 1e300", []
    return None, rows


def plot_search_anytime(path, out):
    """search<k>_gap.png from search_anytime.csv: best and bound over time; the files written. A
    file that is no search curve (anytime_problem()) is named on stderr and not drawn."""
    if not os.path.exists(path):
        return []
    y_label = objective_label(os.path.dirname(path))
    problem, rows = anytime_problem(path)
    if problem:
        print(f"plot.py: {path}: {problem}; its gap curve is not drawn", file=sys.stderr)
        return []
    curves = {}
    for r in rows:
        curves.setdefault(r["search_id"], []).append(r)
    written = []
    for search, points in curves.items():
        longest = max(number(r["elapsed_s"]) for r in points)
        unit, per = ("s", 1.0) if longest < 120 else ("min", 60.0) if longest < 7200 else ("h", 3600.0)
        t = [number(r["elapsed_s"]) / per for r in points]
        best = [number(r["best"]) for r in points]
        bound = [number(r["bound"]) for r in points]
        labels = ["best objective found", "certified bound of the optimum", "gap"]
        stops = [k for k, r in enumerate(points) if r["status"] == "stopped"]
        if stops:
            labels.append("stopped (resumed after)")
        legend_in = legend_height_in(labels, 7.0)
        fig, (ax, legend_ax) = plt.subplots(2, 1, figsize=(7.0, 4.5 + legend_in), layout="constrained",
                                            gridspec_kw={"height_ratios": [4.5, legend_in]})
        # Markers on a short curve: a search stopped early may have a single point.
        marker = "o" if len(t) <= 20 else None
        ax.step(t, best, where="post", color="tab:blue", marker=marker, markersize=3, label="best objective found")
        ax.step(t, bound, where="post", color="tab:red", marker=marker, markersize=3,
                label="certified bound of the optimum")
        ax.fill_between(t, bound, best, step="post", color="tab:grey", alpha=0.25, label="gap")
        if stops:  # on the best found, or on the bound before any was found
            ax.plot([t[k] for k in stops], [bound[k] if math.isnan(best[k]) else best[k] for k in stops], "kx",
                    label="stopped (resumed after)")
        last = points[-1]
        gap = number(last["relative_gap"])
        state = {"finished": "finished", "stopped": "stopped", "running": "running"}.get(last["status"], "")
        seconds = number(last["elapsed_s"])
        took = (f"{seconds:.2g} s" if seconds < 60 else f"{seconds / 60:.3g} min" if seconds < 3600
                else f"{seconds / 3600:.3g} h")
        ax.set_title(wrapped(f"exact search {search}: {state} after {took}, "
                             f"{int(number(last['resolved_vectors'])):,} of {int(number(last['vectors'])):,} "
                             "vectors resolved, "
                             + (f"gap {100.0 * gap:.3g}%" if not math.isnan(gap) else "gap unknown"), 70),
                     fontsize=10)
        ax.set_xlabel(f"search time ({unit}, over every resumed process)", fontsize=11)
        ax.set_ylabel(y_label, fontsize=11)
        ax.yaxis.set_major_formatter(FuncFormatter(thousands(ax.get_yticks())))
        ax.grid(alpha=0.3)
        handles, labels = ax.get_legend_handles_labels()
        legend_below(fig, legend_ax, handles, labels, 7.0)
        written.append(save(fig, out, f"search{search}_gap.png"))
    return written


def write_layout(path):
    """The figures' bounding boxes (LAYOUT) as JSON at `path` (--layout-json); nothing without one."""
    if path:
        with open(path, "w", encoding="utf-8") as f:
            json.dump(LAYOUT, f, indent=1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir", help="sweep output directory (aggregated)")
    parser.add_argument("--out", help="directory for the PNGs (default: DIR/plots)")
    parser.add_argument("--top", type=int, default=8, help="most configurations per map class (default 8)")
    parser.add_argument("--layout-json", help="write the figures' bounding boxes to this file")
    args = parser.parse_args()
    out = args.out or os.path.join(args.dir, "plots")
    os.makedirs(out, exist_ok=True)

    anytime = os.path.join(args.dir, "search_anytime.csv")
    if not os.path.exists(os.path.join(args.dir, "summary.csv")) and os.path.exists(anytime):
        # A stopped weight search: its curve is all there is to draw.
        written = plot_search_anytime(anytime, out)
        write_layout(args.layout_json)
        print(f"wrote {', '.join(os.path.join(out, w) for w in written)}")
        return
    summary_header, summary_rows = read_csv(os.path.join(args.dir, "summary.csv"))
    _, progress_rows = read_csv(os.path.join(args.dir, "progress_summary.csv"))
    best_header, best_rows = read_csv(os.path.join(args.dir, "best.csv"))
    labels, classes = config_labels(summary_header, summary_rows)
    shown, per_class, cut = shown_configs(best_rows, classes, args.top)
    shown_labels = {i: labels[i] for ids in shown.values() for i in ids}
    # Names from what differs among the drawn configurations only.
    drawn = [r for r in summary_rows if r["config_id"] in shown_labels]
    if drawn:
        labels, _ = config_labels(summary_header, drawn)
    note = selection_note(per_class, shown, objective_of(best_header), cut)

    written = [plot_progress(progress_rows, shown, labels, note, out),
               plot_metrics(summary_header, summary_rows, shown, labels, note, out)]
    written += plot_heatmaps(summary_header, summary_rows, best_header, best_rows, out)
    written += plot_search_heatmaps(os.path.join(args.dir, "search_heatmaps.csv"), out)
    written += plot_search_anytime(anytime, out)
    write_layout(args.layout_json)
    print(f"wrote {', '.join(os.path.join(out, w) for w in written)}")


if __name__ == "__main__":
    main()
