#!/usr/bin/env python3
"""The bad-input corpus: runs `fsweep` on every case of cases.json and checks that it refuses
the input with exit code 2 and a message naming what is wrong.

Usage: run_bad_inputs.py FSWEEP [CASES_JSON]

Each case: "file" (in this folder), "args" (fsweep's arguments, "{file}" replaced by the
file's absolute path), "exit" (expected exit code) and "message" (a fragment the stderr
must contain, "{dir}" replaced by this folder's absolute path). Every case runs in a fresh
temporary directory, so nothing is written into the source tree.
"""
import json
import os
import subprocess
import sys
import tempfile

TIMEOUT_S = 60
MAX_STDERR = 2000  # a message longer than this dumped something it should have cut


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 2
    fsweep = os.path.abspath(sys.argv[1])
    here = os.path.dirname(os.path.abspath(__file__))
    cases_path = sys.argv[2] if len(sys.argv) == 3 else os.path.join(here, "cases.json")
    with open(cases_path, encoding="utf-8") as f:
        cases = json.load(f)["cases"]
    failures = []
    for case in cases:
        path = os.path.join(here, case["file"])
        args = [a.replace("{file}", path) for a in case["args"]]
        expected = case["message"].replace("{dir}", here)
        with tempfile.TemporaryDirectory(prefix="fsweep_bad_input_") as work:
            try:
                run = subprocess.run([fsweep, *args], cwd=work, capture_output=True, text=True,
                                     errors="replace", timeout=TIMEOUT_S, check=False)
            except subprocess.TimeoutExpired:
                failures.append(f"{case['file']}: no answer within {TIMEOUT_S} s")
                continue
        problems = []
        if run.returncode != case["exit"]:
            problems.append(f"exit code {run.returncode}, expected {case['exit']}")
        if expected not in run.stderr:
            problems.append(f"stderr lacks {expected!r}")
        if len(run.stderr) > MAX_STDERR:
            problems.append(f"stderr has {len(run.stderr)} characters; allowed: {MAX_STDERR}")
        status = "ok" if not problems else "FAILED: " + "; ".join(problems)
        print(f"{case['file']}: {status}")
        if problems:
            failures.append(f"{case['file']}: {'; '.join(problems)}\n  stderr: {run.stderr[:MAX_STDERR]!r}")
    if failures:
        print(f"\n{len(failures)} of {len(cases)} cases failed:", file=sys.stderr)
        for failure in failures:
            print(failure, file=sys.stderr)
        return 1
    print(f"all {len(cases)} bad inputs refused as expected")
    return 0


if __name__ == "__main__":
    sys.exit(main())
