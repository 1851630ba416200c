#!/usr/bin/python3
"""Paired comparison of two strategies of one sweep (Mei 2006 section V-C style).

Usage:
  tools/paired_compare.py DIR --a LABEL_A --b LABEL_B [--out PREFIX] [--plot PNG_PREFIX]
                          [--step-m 5]

Reads DIR/runs.csv and DIR/progress.csv (written by `fsweep run`). Runs are told apart by
their `strategy_label` column; LABEL_A and LABEL_B name the two sides (e.g. `orientation`
and `widest_frontier`). A run of A is paired with the run of B that has the same values in
every configuration column other than the strategy's (map_class, map, planner, robot.*,
sim.*, seed: every column from map_class to seed except strategy_label, strategy and
strategy.*), i.e. the same map instance (generator seed), robot and run seed. Unpaired runs
are counted and left out.

Per pair:
  shorter_pct = 100 (d_B - d_A) / d_B     (% shorter distance of A; distance_m)
  less_energy_pct = 100 (e_B - e_A) / e_B (% less energy of A; energy)
  Coverage curves are step functions of the distance travelled (progress.csv samples, each
  run's last sample held after its end). B "leads" at a sample distance x (of either run)
  when its coverage exceeds A's by more than 1e-9.
  b_leads_first: the first sample where the curves differ has B ahead (B leads early).
  first_crossover_m: for those pairs, the first sample after B's early lead at which A is not
    behind any more (A catches up); empty (NaN) when A is ahead first.
  last_crossover_m: the end of the last interval in which B leads (from there on A is never
    behind); 0 when B never leads. When B still leads at the last sample (A completes later),
    it is that sample's distance and b_leads_to_end is set.
  b_lead_share: of the sample distances where the curves differ, the share where B leads
    (about the share of the way, samples being every progress_step_m); empty if never.

Per map class (and planner/robot variant: the key without map, map.* and seed): n pairs,
median and q05/q95 (linear interpolation, numpy's default type 7, as `fsweep aggregate`) of
shorter_pct, less_energy_pct, first_crossover_m (over the pairs where B leads first),
last_crossover_m and b_lead_share; the number of pairs where A is shorter, where B leads first and where B
leads to the end; metres_per_step, the pooled distance over the pooled steps of both sides
(to convert metres to the paper's steps, one step per move to an 8-neighbour); and
median_curve_crossover_m, the end of the last --step-m grid interval in which B's median
coverage (over the class's pairs) exceeds A's.

Writes PREFIX_pairs.csv and PREFIX_summary.csv (PREFIX defaults to DIR/paired) and prints
the summary. With --plot, writes PNG_PREFIX<class>.png per class: median coverage vs
distance of A and B with q05-q95 bands (the paper's Figures 11-13 over many maps).
Needs Python 3; --plot also needs matplotlib. Output is deterministic.
"""

import argparse
import csv
import math
import os
import re
import sys

EPS = 1e-9
METRICS = ("shorter_pct", "less_energy_pct", "first_crossover_m", "last_crossover_m", "b_lead_share")


def read_csv(path):
    """Header and rows (dicts); exits with a message naming a missing file."""
    if not os.path.exists(path):
        sys.exit(f"paired_compare.py: {path}: not found (run `fsweep run` first)")
    with open(path, newline="", encoding="utf-8") as f:
        reader = csv.DictReader(f)
        return reader.fieldnames or [], list(reader)


def quantile(values, q):
    """Type-7 quantile of a non-empty list (linear interpolation between order statistics)."""
    v = sorted(values)
    if not v:
        return math.nan
    h = (len(v) - 1) * q
    lo = math.floor(h)
    hi = min(lo + 1, len(v) - 1)
    return v[lo] + (h - lo) * (v[hi] - v[lo])


def key_columns(header):
    """Configuration columns that identify a pair: map_class .. seed without the strategy."""
    start = header.index("map_class")
    stop = header.index("seed")
    cols = header[start : stop + 1]
    return [c for c in cols if c not in ("strategy_label", "strategy") and not c.startswith("strategy.")]


def curve(samples):
    """(distances, coverages) of one run, sorted by distance."""
    samples = sorted(samples)
    return [s[0] for s in samples], [s[1] for s in samples]


def coverage_at(c, x):
    """Coverage of a step curve at distance x: the last sample at or before x (0 before)."""
    xs, ys = c
    lo, hi = 0, len(xs)
    while lo < hi:  # first index with xs[i] > x
        mid = (lo + hi) // 2
        if xs[mid] <= x:
            lo = mid + 1
        else:
            hi = mid
    return ys[lo - 1] if lo > 0 else 0.0


def crossover(ca, cb):
    """Lead statistics of two coverage step curves A (ca) and B (cb), see the module doc:
    (b_leads_first, first_crossover_m, last_crossover_m, b_leads_to_end, b_lead_share)."""
    xs = sorted(set(ca[0]) | set(cb[0]))
    diff = [coverage_at(cb, x) - coverage_at(ca, x) for x in xs]
    first_sign = next((d for d in diff if abs(d) > EPS), 0.0)
    b_leads_first = first_sign > 0.0
    first_cross = 0.0
    if b_leads_first:
        led = False
        for x, d in zip(xs, diff):
            if d > EPS:
                led = True
            elif led:
                first_cross = x
                break
    last_cross = 0.0
    leads_to_end = False
    for i, d in enumerate(diff):
        if d > EPS:
            if i + 1 < len(xs):
                last_cross = xs[i + 1]
            else:
                last_cross = xs[i]
                leads_to_end = True
    if b_leads_first and first_cross == 0.0:
        first_cross = last_cross  # B led to the end
    if not b_leads_first:
        first_cross = math.nan
    ahead_b = sum(d > EPS for d in diff)
    ahead_a = sum(d < -EPS for d in diff)
    share = ahead_b / (ahead_a + ahead_b) if ahead_a + ahead_b else math.nan
    return b_leads_first, first_cross, last_cross, leads_to_end, share


def cell(value):
    """A CSV cell: floats with 6 significant digits, NaN empty."""
    if isinstance(value, float):
        return "" if math.isnan(value) else f"{value:.6g}"
    return value


def safe_name(text):
    """A map class as a file name part."""
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", text).strip("_") or "all"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("dir", help="sweep output directory (runs.csv, progress.csv)")
    ap.add_argument("--a", required=True, help="strategy_label of side A")
    ap.add_argument("--b", required=True, help="strategy_label of side B")
    ap.add_argument("--out", help="output prefix (default DIR/paired)")
    ap.add_argument("--plot", help="PNG prefix: one coverage-vs-distance figure per map class")
    ap.add_argument("--step-m", type=float, default=5.0, help="grid of the median curves (m)")
    args = ap.parse_args()
    out = args.out or os.path.join(args.dir, "paired")

    header, runs = read_csv(os.path.join(args.dir, "runs.csv"))
    _, progress = read_csv(os.path.join(args.dir, "progress.csv"))
    keys = key_columns(header)
    samples = {}
    for p in progress:
        samples.setdefault(p["run_index"], []).append((float(p["distance_m"]), float(p["coverage"])))

    sides = {args.a: {}, args.b: {}}
    for r in runs:
        label = r["strategy_label"]
        if label in sides:
            k = tuple(r[c] for c in keys)
            if k in sides[label]:
                sys.exit(f"paired_compare.py: two runs of {label} with the same key {k}")
            sides[label][k] = r
    for label, found in sides.items():
        if not found:
            labels = sorted({r["strategy_label"] for r in runs})
            sys.exit(f"paired_compare.py: no run labelled {label!r}; labels: {', '.join(labels)}")
    common = sorted(set(sides[args.a]) & set(sides[args.b]))
    unpaired = len(sides[args.a]) + len(sides[args.b]) - 2 * len(common)

    group_cols = [c for c in keys if c not in ("map", "seed") and not c.startswith("map.")]
    pairs = []
    for k in common:
        ra, rb = sides[args.a][k], sides[args.b][k]
        ca = curve(samples.get(ra["run_index"], [(0.0, 0.0)]))
        cb = curve(samples.get(rb["run_index"], [(0.0, 0.0)]))
        first, x_first, x_last, to_end, share = crossover(ca, cb)
        da, db = float(ra["distance_m"]), float(rb["distance_m"])
        ea, eb = float(ra["energy"]), float(rb["energy"])
        pairs.append({
            "group": tuple(ra[c] for c in group_cols),
            "map_class": ra["map_class"], "map": ra["map"], "seed": ra["seed"],
            "end_a": ra["end_reason"], "end_b": rb["end_reason"],
            "distance_a": da, "distance_b": db, "energy_a": ea, "energy_b": eb,
            "shorter_pct": 100.0 * (db - da) / db if db > 0 else math.nan,
            "less_energy_pct": 100.0 * (eb - ea) / eb if eb > 0 else math.nan,
            "steps_a": int(ra["steps"]), "steps_b": int(rb["steps"]),
            "b_leads_first": first, "first_crossover_m": x_first, "last_crossover_m": x_last,
            "b_leads_to_end": to_end, "b_lead_share": share,
            "curves": (ca, cb),
        })

    pair_cols = ["map_class", "map", "seed", "end_a", "end_b", "distance_a", "distance_b", "energy_a",
                 "energy_b", "steps_a", "steps_b", "shorter_pct", "less_energy_pct", "b_leads_first",
                 "first_crossover_m", "last_crossover_m", "b_leads_to_end", "b_lead_share"]
    with open(out + "_pairs.csv", "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(pair_cols)
        for p in pairs:
            w.writerow([cell(p[c]) for c in pair_cols])

    groups = {}
    for p in pairs:
        groups.setdefault(p["group"], []).append(p)
    summary_cols = (["map_class"] + [c for c in group_cols if c != "map_class"] +
                    ["n", "a_shorter", "b_leads_first", "b_leads_to_end", "distance_a.median",
                     "distance_b.median", "energy_a.median", "energy_b.median", "metres_per_step"] +
                    [f"{m}.{q}" for m in METRICS for q in ("median", "q05", "q95")] +
                    ["median_curve_crossover_m"])
    rows = []
    for g, ps in sorted(groups.items()):
        row = dict(zip(group_cols, g))
        row["n"] = len(ps)
        row["a_shorter"] = sum(p["distance_a"] < p["distance_b"] for p in ps)
        row["b_leads_first"] = sum(p["b_leads_first"] for p in ps)
        row["b_leads_to_end"] = sum(p["b_leads_to_end"] for p in ps)
        for m in ("distance_a", "distance_b", "energy_a", "energy_b"):
            row[m + ".median"] = quantile([p[m] for p in ps], 0.5)
        steps = sum(p["steps_a"] + p["steps_b"] for p in ps)
        metres = sum(p["distance_a"] + p["distance_b"] for p in ps)
        row["metres_per_step"] = metres / steps if steps else math.nan
        for m in METRICS:
            vals = [p[m] for p in ps if not math.isnan(p[m])]
            for q, name in ((0.5, "median"), (0.05, "q05"), (0.95, "q95")):
                row[f"{m}.{name}"] = quantile(vals, q)
        grid, med = median_curves(ps, args.step_m)
        row["median_curve_crossover_m"] = median_crossover(grid, med)
        row["_curves"] = (grid, med)
        rows.append(row)

    with open(out + "_summary.csv", "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(summary_cols)
        for row in rows:
            w.writerow([cell(row[c]) for c in summary_cols])

    print(f"A = {args.a}, B = {args.b}; {len(pairs)} pairs, {unpaired} unpaired runs left out")
    for row in rows:
        print(describe(row))
    if args.plot:
        plot(rows, args)


def spread(row, metric, scale=1.0, digits=1):
    """'median [q05, q95]' of a summary metric, multiplied by scale."""
    m, lo, hi = (scale * row[f"{metric}.{q}"] for q in ("median", "q05", "q95"))
    return f"{m:.{digits}f} [{lo:.{digits}f}, {hi:.{digits}f}]"


def describe(row):
    """One printed line per summary row."""
    return (f"{row['map_class']}: n={row['n']}, A shorter in {row['a_shorter']}; "
            f"distance A {row['distance_a.median']:.1f} vs B {row['distance_b.median']:.1f}, "
            f"% shorter {spread(row, 'shorter_pct')}, % less energy {spread(row, 'less_energy_pct')}; "
            f"B ahead first in {row['b_leads_first']}, to the end in {row['b_leads_to_end']}; "
            f"A catches up at {spread(row, 'first_crossover_m', digits=0)} m, "
            f"B's last lead ends at {spread(row, 'last_crossover_m', digits=0)} m; "
            f"median curves cross at {row['median_curve_crossover_m']:.0f} m; "
            f"B ahead on {spread(row, 'b_lead_share', 100.0, 0)}% of the way where they differ; "
            f"{row['metres_per_step']:.3f} m per step")


def median_curves(ps, step):
    """Grid of distances and, per side, (q05, median, q95) coverage over the pairs' runs."""
    end = max(max(p["curves"][0][0][-1], p["curves"][1][0][-1]) for p in ps)
    n = int(math.ceil(end / step)) + 1
    grid = [i * step for i in range(n)]
    med = []
    for side in (0, 1):
        bands = []
        for x in grid:
            vals = [coverage_at(p["curves"][side], x) for p in ps]
            bands.append((quantile(vals, 0.05), quantile(vals, 0.5), quantile(vals, 0.95)))
        med.append(bands)
    return grid, med


def median_crossover(grid, med):
    """End of the last grid interval where B's median coverage exceeds A's (0: never)."""
    last = 0.0
    for i, x in enumerate(grid):
        if med[1][i][1] > med[0][i][1] + EPS:
            last = grid[i + 1] if i + 1 < len(grid) else x
    return last


def plot(rows, args):
    """One PNG per group: median coverage vs distance with q05-q95 bands."""
    try:
        import matplotlib
    except ImportError:
        sys.exit("paired_compare.py: --plot needs matplotlib (Debian's python3-matplotlib, /usr/bin/python3)")

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    for row in rows:
        grid, med = row["_curves"]
        fig, ax = plt.subplots(figsize=(5.0, 3.2))
        for side, (label, colour) in enumerate(((args.a, "tab:blue"), (args.b, "tab:red"))):
            ax.fill_between(grid, [b[0] for b in med[side]], [b[2] for b in med[side]], color=colour,
                            alpha=0.15, linewidth=0)
            ax.plot(grid, [b[1] for b in med[side]], color=colour, label=f"{label} (median, q05-q95)")
        if row["median_curve_crossover_m"] > 0:
            ax.axvline(row["median_curve_crossover_m"], color="grey", linestyle=":", linewidth=1)
        ax.set_xlabel("distance travelled (m = cells at resolution 1)")
        ax.set_ylabel("coverage ratio")
        ax.set_ylim(0, 1.02)
        ax.set_title(f"{row['map_class']}: {row['n']} maps", fontsize=9)
        ax.legend(fontsize=7, loc="lower right")
        ax.grid(alpha=0.3)
        fig.tight_layout()
        name = f"{args.plot}{safe_name(row['map_class'])}.png"
        fig.savefig(name, dpi=80, metadata={"Software": None})
        plt.close(fig)


if __name__ == "__main__":
    main()
