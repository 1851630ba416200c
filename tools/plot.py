#!/usr/bin/python3
"""Figures of an aggregated sweep (run by `fsweep plot DIR`).

Reads DIR/summary.csv, DIR/progress_summary.csv and DIR/best.csv (written by
`fsweep aggregate`, src/report/aggregate.hpp) and writes to --out (default DIR/plots):

  progress.png           explored area vs distance: mean line and q05-q95 band per configuration
                         (Rappaport 2016, Figure 4)
  metrics.png            median with q05-q95 bars of distance, energy, coverage and distance to
                         the final coverage, per configuration
  heatmap_<wi>_<wj>.png  weight searches (at least three values in each of at least two of
                         strategy.w1..w4): the objective's median over each pair of weights, the
                         best value over the other weights and columns
  search<k>_<wa>_<wb>.png  exact weight searches (DIR/search_heatmaps.csv, written by `fsweep
                         run` for a search of mode "all"): per search k and pair of weights with
                         at least two values each, the best objective of any weight vector with
                         those two values

With many configurations, progress.png and metrics.png show the best ones by best.csv's ranking
(at most --top). Needs Python 3 and matplotlib only; output is deterministic (no timestamps).
"""

import argparse
import csv
import itertools
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402

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
    """Column name without the strategy./robot. prefix, for labels."""
    for prefix in ("strategy.", "robot."):
        if column.startswith(prefix):
            return column[len(prefix):]
    return column


def config_labels(header, rows):
    """config_id -> 'strategy k=v ...' with the config columns that differ between rows."""
    config_cols = header[header.index("config_id") + 1:header.index("n")]
    # Columns with more than one value (an empty cell, a parameter another strategy lacks, aside).
    differing = [c for c in config_cols if c != "strategy" and len({r[c] for r in rows if r[c] != ""}) > 1]
    # A sweep's strategy labels ("EA free") stand for the strategy and its parameters.
    # When one label covers several parameter sets (a weight grid), the parameters still show.
    if "strategy_label" in config_cols:
        params = [c for c in config_cols if c.startswith("strategy.")]
        sets = {}
        for r in rows:
            sets.setdefault(r["strategy_label"], set()).add(tuple(r[c] for c in params))
        shared = any(len(v) > 1 for v in sets.values())
        differing = [c for c in differing
                     if c != "strategy_label" and (shared or not c.startswith("strategy."))]
    labels = {}
    for r in rows:
        if "strategy_label" in config_cols:
            parts = [r["strategy_label"]]
        else:
            parts = [r.get("strategy", "")] if "strategy" in config_cols else []
        parts += [f"{short_name(c)}={r[c]}" for c in differing if r[c] != ""]
        labels[r["config_id"]] = " ".join(p for p in parts if p) or f"config {r['config_id']}"
    return labels


def shown_configs(best_header, best_rows, top):
    """config_ids to draw in best.csv's order: all, or the best `top`; and a note for titles."""
    ids = [r["config_id"] for r in best_rows]
    median_col = next((c for c in best_header if c.endswith(".median")), "objective.median")
    objective = median_col[:-len(".median")]
    if len(ids) <= top:
        return ids, f"\nconfigurations by median {objective}"
    return ids[:top], f"\nbest {top} of {len(ids)} configurations by median {objective}"


def plot_progress(progress_rows, ids, labels, note, out):
    curves = {i: [] for i in ids}
    for r in progress_rows:
        if r["config_id"] in curves:
            curves[r["config_id"]].append(r)
    fig, ax = plt.subplots(figsize=(9, 5.5))
    colors = plt.get_cmap("tab10")
    for k, config_id in enumerate(ids):
        rows = sorted(curves[config_id], key=lambda r: number(r["distance_m"]))
        if not rows:
            continue
        d = [number(r["distance_m"]) for r in rows]
        color = colors(k % 10)
        ax.fill_between(d, [number(r["explored_area_m2.q05"]) for r in rows],
                        [number(r["explored_area_m2.q95"]) for r in rows], color=color, alpha=0.18, linewidth=0)
        ax.plot(d, [number(r["explored_area_m2.mean"]) for r in rows], color=color, linewidth=1.6,
                marker="o" if len(d) == 1 else None, label=f"{labels[config_id]} (n={rows[0]['n']})")
    ax.set_xlabel("distance travelled (m)", fontsize=11)
    ax.set_ylabel("explored area (m²)", fontsize=11)
    ax.set_title("Explored area vs distance: mean, q05–q95 band" + note, fontsize=11)
    ax.grid(True, alpha=0.3)
    ax.set_xlim(left=0)
    ax.set_ylim(bottom=0)
    if ids:
        ax.legend(fontsize=8, loc="lower right", framealpha=0.9)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "progress.png"), **SAVE)
    plt.close(fig)


def plot_metrics(summary_header, summary_rows, ids, labels, note, out):
    by_id = {r["config_id"]: r for r in summary_rows}
    metrics = [(m, t) for m, t in METRICS if f"{m}.median" in summary_header]
    cols = 2
    rows_n = max(1, math.ceil(len(metrics) / cols))
    height = max(3.0, 0.32 * len(ids) + 1.5)
    fig, axes = plt.subplots(rows_n, cols, figsize=(12, height * rows_n), squeeze=False)
    y = list(range(len(ids)))
    names = [labels[i] for i in ids]
    colors = plt.get_cmap("tab10")  # the same colour per configuration as in progress.png
    for k, (metric, title) in enumerate(metrics):
        ax = axes[k // cols][k % cols]
        med = [number(by_id[i][f"{metric}.median"]) for i in ids]
        lo = [max(0.0, m - number(by_id[i][f"{metric}.q05"])) for m, i in zip(med, ids)]
        hi = [max(0.0, number(by_id[i][f"{metric}.q95"]) - m) for m, i in zip(med, ids)]
        ax.barh(y, med, xerr=[lo, hi], color=[colors(k % 10) for k in y], alpha=0.8,
                error_kw={"ecolor": "black", "capsize": 3})
        ax.set_yticks(y)
        ax.set_yticklabels(names if k % cols == 0 else [], fontsize=8)
        ax.invert_yaxis()  # best first, at the top
        ax.set_title(title, fontsize=11)
        ax.grid(True, axis="x", alpha=0.3)
    for k in range(len(metrics), rows_n * cols):
        axes[k // cols][k % cols].set_visible(False)
    fig.suptitle("Median per configuration, bars q05–q95" + note, fontsize=11)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "metrics.png"), **SAVE)
    plt.close(fig)


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
            x, y, v = number(s[wi]), number(s[wj]), number(r[median_col])
            if math.isnan(x) or math.isnan(y) or math.isnan(v):
                continue
            cells[(x, y)] = better(cells[(x, y)], v) if (x, y) in cells else v
        if not cells:
            continue
        xs = sorted({x for x, _ in cells})
        ys = sorted({y for _, y in cells})
        grid = [[cells.get((x, y), math.nan) for x in xs] for y in ys]
        fig, ax = plt.subplots(figsize=(max(6.0, 0.42 * len(xs) + 2.5), max(4.5, 0.36 * len(ys) + 1.8)))
        cmap = plt.get_cmap("viridis" if objective in MAXIMISED else "viridis_r").copy()
        cmap.set_bad("lightgrey")
        image = ax.imshow(grid, origin="lower", cmap=cmap, aspect="auto")
        value_ticks(ax, xs, ys)
        ax.set_xlabel(short_name(wi), fontsize=11)
        ax.set_ylabel(short_name(wj), fontsize=11)
        # Values are printed only where the cells are wide enough for them.
        if len(xs) <= 8 and len(ys) <= 12:
            for (x, y), v in cells.items():
                ax.text(xs.index(x), ys.index(y), compact(v), ha="center", va="center", fontsize=7, color="white",
                        bbox={"facecolor": "black", "alpha": 0.25, "pad": 1, "linewidth": 0})
        # The best cell (ties: smallest weights) framed in red.
        bx, by = min(cells, key=lambda c: (-cells[c] if objective in MAXIMISED else cells[c], c))
        ax.add_patch(Rectangle((xs.index(bx) - 0.5, ys.index(by) - 0.5), 1, 1, fill=False, edgecolor="red",
                               linewidth=2.5))
        ax.set_title(f"median {objective}\n({'max' if better is max else 'min'} over {others}; best framed)"
                     if others else f"median {objective} (best framed)", fontsize=10)
        written.append(save_heatmap(fig, ax, image, f"median {objective}", out,
                                    f"heatmap_{short_name(wi)}_{short_name(wj)}.png"))
    return written


def value_ticks(ax, xs, ys):
    """Tick labels of a heat map's cells: the values `xs`, `ys`, at most about 15 of each."""
    step_x = max(1, math.ceil(len(xs) / 15))
    step_y = max(1, math.ceil(len(ys) / 15))
    ax.set_xticks(range(0, len(xs), step_x))
    ax.set_xticklabels([f"{xs[k]:g}" for k in range(0, len(xs), step_x)], fontsize=8)
    ax.set_yticks(range(0, len(ys), step_y))
    ax.set_yticklabels([f"{ys[k]:g}" for k in range(0, len(ys), step_y)], fontsize=8)


def save_heatmap(fig, ax, image, label, out, name):
    """Colour bar, layout, the PNG `name` in `out`; returns `name`."""
    fig.colorbar(image, ax=ax, label=label)
    fig.tight_layout()
    fig.savefig(os.path.join(out, name), **SAVE)
    plt.close(fig)
    return name


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
        fig, ax = plt.subplots(figsize=(7.0, 5.5))
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
        ax.set_title(f"exact search {search}: best objective over the other weights (best framed)", fontsize=10)
        written.append(save_heatmap(fig, ax, image, "best objective", out, f"search{search}_{wa}_{wb}.png"))
    return written


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir", help="sweep output directory (aggregated)")
    parser.add_argument("--out", help="directory for the PNGs (default: DIR/plots)")
    parser.add_argument("--top", type=int, default=10, help="most configurations per figure (default 10)")
    args = parser.parse_args()
    out = args.out or os.path.join(args.dir, "plots")
    os.makedirs(out, exist_ok=True)

    summary_header, summary_rows = read_csv(os.path.join(args.dir, "summary.csv"))
    _, progress_rows = read_csv(os.path.join(args.dir, "progress_summary.csv"))
    best_header, best_rows = read_csv(os.path.join(args.dir, "best.csv"))
    labels = config_labels(summary_header, summary_rows)
    ids, note = shown_configs(best_header, best_rows, args.top)

    plot_progress(progress_rows, ids, labels, note, out)
    plot_metrics(summary_header, summary_rows, ids, labels, note, out)
    written = ["progress.png", "metrics.png"]
    written += plot_heatmaps(summary_header, summary_rows, best_header, best_rows, out)
    written += plot_search_heatmaps(os.path.join(args.dir, "search_heatmaps.csv"), out)
    print(f"wrote {', '.join(os.path.join(out, w) for w in written)}")


if __name__ == "__main__":
    main()
