#!/usr/bin/env python3
"""scripts/ctest-failures on a made-up ctest log: the failed test's output is repeated (its last
lines), the passed test's is not, and a build tree without a log is no error."""
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "..", "..", "scripts", "ctest-failures")

LOG = """Start testing: Dec 05 15:04 UTC
----------------------------------------------------------
1/2 Testing: Good.Test
1/2 Test: Good.Test
Command: "/bin/true"
Output:
----------------------------------------------------------
all fine here
<end of output>
Test time =   0.01 sec
----------------------------------------------------------
Test Passed.

2/2 Testing: Bad.Test
2/2 Test: Bad.Test
Command: "/bin/false"
Output:
----------------------------------------------------------
{lines}
<end of output>
Test time =   0.02 sec
----------------------------------------------------------
Test Failed.
"""


def main():
    failures = []
    with tempfile.TemporaryDirectory() as build:
        os.makedirs(os.path.join(build, "Testing", "Temporary"))
        lines = "\n".join(f"line {i}" for i in range(1, 101))
        with open(os.path.join(build, "Testing", "Temporary", "LastTest.log"), "w", encoding="utf-8") as f:
            f.write(LOG.format(lines=lines))
        out = subprocess.run([sys.executable, SCRIPT, build, "--lines", "10"], capture_output=True, text=True)
        text = out.stdout
        if out.returncode != 0:
            failures.append(f"exit {out.returncode}")
        if "failed: Bad.Test (last 10 of 100 lines)" not in text:
            failures.append("no header for Bad.Test")
        if "line 100" not in text or "line 91" not in text or "line 90\n" in text:
            failures.append("not exactly the last 10 lines")
        if "Good.Test" in text or "all fine here" in text:
            failures.append("the passed test is repeated")
        if "1 failed test(s)" not in text:
            failures.append("no count")
    with tempfile.TemporaryDirectory() as empty:
        out = subprocess.run([sys.executable, SCRIPT, empty], capture_output=True, text=True)
        if out.returncode != 0 or out.stdout:
            failures.append(f"a tree without a log: exit {out.returncode}, output {out.stdout!r}")
    for f in failures:
        print("FAIL", f)
    print(f"check_ctest_failures.py: {len(failures)} problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
