#!/usr/bin/python3
"""The figures of `fsweep plot` fit their pictures: checked from matplotlib's own bounding boxes.

Draws the plots (tools/plot.py --layout-json) of three sweeps and checks every figure:
- every text (figure title, panel titles, axis labels, tick labels) and every legend lies inside
  the figure (1 pixel of slack);
- no legend overlaps a panel (the axes' area), and the figure title overlaps none;
- no two panels overlap;
- a weight search's gap curve names its objective on the y axis ("distance to final coverage
  (m)"), and its y tick labels differ from each other and carry thousands separators; the
  label and tick helpers are also checked directly on made-up manifests and ticks.
The sweeps: sweeps/examples/strategies_planners.json (48 configurations, 2 map classes), the
default sweep, a small exact weight search of mode best (its gap curve), the same search over the
full box [0, 250]^4 stopped by a Ctrl-C after 2 s (a directory with only its gap curve to draw),
and the nightly suite's 702 configurations from the committed baseline
(results/baseline/nightly/runs.csv, 6 map classes), whose progress.csv is made here from each
run's final explored area (the layout is what is checked, not the curves).

Usage: check_plot_layout.py FSWEEP --work DIR. Exit 0 when every figure fits, 1 listing what
does not; the PNGs and layout.json stay in DIR/<sweep>/.
"""

import argparse
import csv
import json
import os
import shutil
import importlib.util
import subprocess
import sys
import tempfile

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SLACK = 1.0


def run(command, cwd=SOURCE):
    r = subprocess.run(command, cwd=cwd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"check_plot_layout.py: {' '.join(command)} failed ({r.returncode}):\n{r.stdout}{r.stderr}")
    return r.stdout


def inside(box, frame):
    return (box[0] >= frame[0] - SLACK and box[1] >= frame[1] - SLACK and box[2] <= frame[2] + SLACK
            and box[3] <= frame[3] + SLACK)


def overlap(a, b):
    return min(a[2], b[2]) - max(a[0], b[0]) > SLACK and min(a[3], b[3]) - max(a[1], b[1]) > SLACK


def problems_of(name, figure):
    frame = figure["figure"]
    out = []
    for t in figure["texts"]:
        if not inside(t["box"], frame):
            out.append(f"{name}: text {t['text'][:60]!r} at {[round(v) for v in t['box']]} leaves the figure "
                       f"{[round(v) for v in frame]}")
    for legend in figure["legends"]:
        if not inside(legend, frame):
            out.append(f"{name}: the legend at {[round(v) for v in legend]} leaves the figure")
        for ax in figure["axes"]:
            if overlap(legend, ax):
                out.append(f"{name}: the legend at {[round(v) for v in legend]} covers a panel at "
                           f"{[round(v) for v in ax]}")
    for i, a in enumerate(figure["axes"]):
        for b in figure["axes"][i + 1:]:
            if overlap(a, b):
                out.append(f"{name}: panels at {[round(v) for v in a]} and {[round(v) for v in b]} overlap")
    titles = [t for t in figure["texts"] if t.get("suptitle")]
    for t in titles:
        for ax in figure["axes"]:
            if overlap(t["box"], ax):
                out.append(f"{name}: the title covers a panel")
    return out


def plot_module():
    spec = importlib.util.spec_from_file_location("plot", os.path.join(SOURCE, "tools", "plot.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def label_problems():
    """The gap curve's y label names the manifest's objective with its unit, and its tick labels
    carry thousands separators and as many decimals as their spacing needs."""
    plot = plot_module()
    out = []
    with tempfile.TemporaryDirectory() as d:
        for manifest, expected in (({"objective": "distance_to_coverage_target_m"}, "distance to coverage target (m)"),
                                   ({"objective": "explored_area_m2"}, "explored area (m²)"),
                                   ({"objective": "time_s"}, "time (s)"),
                                   ({"objective": "stops"}, "stops"),
                                   ({}, "objective"), ([1, 2], "objective"), (None, "objective")):
            path = os.path.join(d, "manifest.json")
            if manifest is None:
                os.remove(path)
            else:
                with open(path, "w", encoding="utf-8") as f:
                    json.dump(manifest, f)
            got = plot.objective_label(d)
            if got != expected:
                out.append(f"objective_label of the manifest {manifest!r}: {got!r}, not {expected!r}")
    # A search_anytime.csv that is no search curve is named and not drawn, never a traceback.
    header = ",".join(("search_id", "elapsed_s", "status", "resolved_vectors", "vectors", "open_branches",
                       "best", "bound", "gap", "relative_gap"))
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "search_anytime.csv")
        for text, expected in (("a,b,c\n1,2,3\n", "no column search_id"),
                               (header + "\n0,1.5,running,10,100,3,50,40,10\n", "line 2 has 10 fields"),
                               (header + "\n0,1.5,running,x,100,3,50,40,10,0.2\n", "line 2: resolved_vectors 'x'"),
                               (header + "\n0,1.5,running,10,100,3,1e308,40,10,0.2\n", "line 2: best '1e308'")):
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
            problem, _ = plot.anytime_problem(path)
            if not problem or expected not in problem:
                out.append(f"anytime_problem of {text!r}: {problem!r}, not one with {expected!r}")
        with open(path, "wb") as f:
            f.write(header.encode() + b"\n\xff\xfe\n")
        if plot.plot_search_anytime(path, d) != []:
            out.append("a search_anytime.csv that is not UTF-8 was drawn")
    for ticks, expected in (([0.0, 5000.0, 10000.0], ["0", "5,000", "10,000"]),
                            ([37017.0, 37017.5, 37018.0], ["37,017.0", "37,017.5", "37,018.0"]),
                            ([-0.04, -0.02, 0.0, 0.02], ["-0.04", "-0.02", "0.00", "0.02"]),
                            ([1234567.0], ["1,234,567"])):
        formatter = plot.thousands(ticks)
        got = [formatter(v, None) for v in ticks]
        if got != expected:
            out.append(f"thousands({ticks}): {got}, not {expected}")
    return out


def gap_label_problems(name, figure, objective_label):
    """A drawn gap curve: its y label is the objective's, and its y tick labels read apart."""
    labels = [t["text"] for t in figure["texts"] if t.get("role") == "ylabel"]
    out = [] if labels == [objective_label] else [f"{name}: the y label is {labels}, not {objective_label!r}"]
    ticks = [t["text"] for t in figure["texts"] if t.get("role") == "ytick"]
    if len(ticks) < 2 or len(set(ticks)) != len(ticks):
        out.append(f"{name}: the y tick labels do not read apart: {ticks}")
    for t in ticks:
        if abs(float(t.replace(",", "").replace("\u2212", "-"))) >= 1000 and "," not in t:
            out.append(f"{name}: the y tick label {t!r} has no thousands separator")
    return out


def nightly_dir(fsweep, work):
    """The committed nightly baseline's runs with a progress.csv of two samples per run."""
    base = os.path.join(SOURCE, "results", "baseline", "nightly")
    out = os.path.join(work, "nightly")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    for f in ("runs.csv", "manifest.json"):
        shutil.copy(os.path.join(base, f), out)
    with open(os.path.join(out, "runs.csv"), newline="", encoding="utf-8") as f, \
            open(os.path.join(out, "progress.csv"), "w", newline="", encoding="utf-8") as p:
        writer = csv.writer(p, lineterminator="\n")
        writer.writerow(["run_index", "run_key", "distance_m", "explored_area_m2", "coverage", "energy"])
        for r in csv.DictReader(f):
            writer.writerow([r["run_index"], r["run_key"], 0, 0, 0, 0])
            writer.writerow([r["run_index"], r["run_key"], r["distance_m"], r["explored_area_m2"], r["coverage"],
                             r["energy"]])
    run([fsweep, "aggregate", out])
    return out


def search_dir(fsweep, work):
    """A small exact weight search of mode best (about a second): its gap curve."""
    out = os.path.join(work, "search")
    sweep = {"schema_version": 1, "name": "search_layout",
             "maps": [{"generator": "free", "w": 71, "h": 71, "res": 10, "label": "free 710 m"}],
             "strategies": [{"name": "energy_aware", "label": "exact",
                             "search": {"method": "exact", "mode": "best", "order": "bound"},
                             "params": {"w1": {"range": [0, 15], "step": 1}, "w2": {"range": [0, 7], "step": 1},
                                        "w3": {"range": [0, 7], "step": 1}, "w4": [0, 1, 2]}}],
             "robot": {"sensor": {"range_m": 30}, "energy": "distance", "battery": 600}, "seed": 2016}
    os.makedirs(work, exist_ok=True)
    path = os.path.join(work, "search_layout.json")
    with open(path, "w", encoding="utf-8") as f:
        json.dump(sweep, f)
    run([fsweep, "run", path, "--quiet", "--fresh", "--out", out])
    return out


def stopped_search_dir(fsweep, work):
    """The same search over a box too large to finish in 2 s, stopped by a Ctrl-C (SIGINT) after
    2 s: no summary.csv, only the gap curve of search_anytime.csv, which `fsweep plot` then draws."""
    out = os.path.join(work, "stopped")
    path = os.path.join(work, "search_layout.json")
    with open(path, encoding="utf-8") as f:
        sweep = json.load(f)
    sweep["name"] = "search_stopped"
    sweep["strategies"][0]["params"] = {"w1": {"range": [0, 250], "step": 1}, "w2": {"range": [0, 250], "step": 1},
                                        "w3": {"range": [0, 250], "step": 1}, "w4": {"range": [0, 250], "step": 1}}
    stopped = os.path.join(work, "search_stopped.json")
    with open(stopped, "w", encoding="utf-8") as f:
        json.dump(sweep, f)
    shutil.rmtree(out, ignore_errors=True)
    r = subprocess.run(["timeout", "--preserve-status", "-s", "INT", "2", fsweep, "run", stopped, "--quiet", "--out", out], cwd=SOURCE,
                       capture_output=True, text=True)
    if r.returncode != 130:
        sys.exit(f"check_plot_layout.py: the stopped search exited {r.returncode}, not 130 (Ctrl-C):\n"
                 f"{r.stdout}{r.stderr}")
    if os.path.exists(os.path.join(out, "summary.csv")) or not os.path.exists(os.path.join(out, "search_anytime.csv")):
        sys.exit("check_plot_layout.py: the stopped search left a summary.csv or no search_anytime.csv")
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("fsweep")
    parser.add_argument("--work", required=True)
    args = parser.parse_args()
    args.work = os.path.abspath(args.work)  # the commands run in the source tree, not here
    if os.sep in args.fsweep:  # a path, not a name on PATH
        args.fsweep = os.path.abspath(args.fsweep)
    os.makedirs(args.work, exist_ok=True)
    problems = label_problems()
    dirs = {}
    for name, sweep in (("strategies_planners", "sweeps/examples/strategies_planners.json"),
                        ("default", "sweeps/default.json")):
        dirs[name] = os.path.join(args.work, name)
        run([args.fsweep, "run", sweep, "--quiet", "--fresh", "--out", dirs[name]])
    dirs["nightly"] = nightly_dir(args.fsweep, args.work)
    dirs["search"] = search_dir(args.fsweep, args.work)
    dirs["stopped"] = stopped_search_dir(args.fsweep, args.work)
    figures = 0
    for name, d in dirs.items():
        layout = os.path.join(d, "layout.json")
        run(["/usr/bin/python3", os.path.join(SOURCE, "tools", "plot.py"), d, "--out", os.path.join(d, "plots"),
             "--layout-json", layout])
        with open(layout, encoding="utf-8") as f:
            for png, figure in json.load(f).items():
                figures += 1
                problems += problems_of(f"{name}/{png}", figure)
                if png == "search0_gap.png":  # the searches' default objective
                    problems += gap_label_problems(f"{name}/{png}", figure, "distance to final coverage (m)")
    if figures < 7:
        problems.append(f"only {figures} figures were drawn")
    if not os.path.exists(os.path.join(dirs["stopped"], "plots", "search0_gap.png")):
        problems.append("the stopped search's gap curve (search0_gap.png) was not drawn")
    for p in problems:
        print(p)
    print(f"check_plot_layout.py: {figures} figures, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
