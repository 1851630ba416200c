#!/usr/bin/python3
"""The docs that run: every command block of the README and docs/ (docs/dev/docs-tests.md).

Reads README.md and every docs/**/*.md page and checks, page by page:
- ```sh blocks run in order, from the root of a scratch copy of the repository (its tracked
  files), with `bash -e -o pipefail`, FSWEEP first on PATH (as `fsweep`) and
  build/release/bin/fsweep pointing at it; a block that exits non-zero fails, naming the page
  and line. `<!-- docs: skip: REASON -->` on the line before a block leaves it out (the reason
  is required); `<!-- docs: long -->` runs it only with --long.
- ```json blocks parse; a whole sweep ("schema_version" in it) passes `fsweep expand`.
- a ```text block marked `<!-- docs: output -->` is the output of the page's previous ```sh
  block: each of its lines (ends trimmed) must appear in that output, in order; a line `...`
  matches any number of lines.

Usage: check_docs.py FSWEEP [--long] [--page PATH ...] [--work DIR] [--jobs N]
Exit 0 when every page passes, 1 listing the failures. Prints each page's time.
"""

import argparse
import concurrent.futures
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MARK = re.compile(r"^<!--\s*docs:\s*(skip|long|output)\s*(?::\s*(.*?))?\s*-->\s*$")
FENCE = re.compile(r"^(\s*)```\s*([A-Za-z0-9_+-]*)\s*$")
SHORT_TIMEOUT_S = 300
LONG_TIMEOUT_S = 4 * 3600


class Block:
    """A fenced block: its page, the line of its opening fence, language, text and mark."""

    def __init__(self, page, line, lang, text, mark, reason):
        self.page, self.line, self.lang, self.text, self.mark, self.reason = page, line, lang, text, mark, reason

    def where(self):
        return f"{self.page}:{self.line}"


def blocks_of(page):
    """The fenced blocks of a Markdown page, with the mark of the line before each."""
    with open(os.path.join(ROOT, page), encoding="utf-8") as f:
        lines = f.read().split("\n")
    out, i = [], 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        indent, lang = m.group(1), m.group(2)
        start = i
        body = []
        i += 1
        while i < len(lines) and lines[i].strip() != "```":
            body.append(lines[i][len(indent):] if lines[i].startswith(indent) else lines[i])
            i += 1
        prev = next((lines[k] for k in range(start - 1, -1, -1) if lines[k].strip()), "")
        mark = MARK.match(prev.strip())
        out.append(Block(page, start + 1, lang, "\n".join(body), mark.group(1) if mark else None,
                         (mark.group(2) or "") if mark else ""))
        i += 1
    return out


def pages():
    found = ["README.md"]
    for base, _, files in os.walk(os.path.join(ROOT, "docs")):
        found += sorted(os.path.relpath(os.path.join(base, f), ROOT) for f in files if f.endswith(".md"))
    return found


def scratch_copy(work, page, fsweep):
    """A copy of the repository's tracked files for one page, with fsweep on its PATH."""
    d = os.path.join(work, re.sub(r"[^A-Za-z0-9]+", "_", page))
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    files = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, check=False).stdout
    names = [n for n in files.decode().split("\0") if n]
    if not names:  # not a git checkout: the source folders
        names = [os.path.relpath(os.path.join(b, f), ROOT) for top in ("sweeps", "tools", "tests", "docs")
                 for b, _, fs in os.walk(os.path.join(ROOT, top)) for f in fs]
    for n in names:
        src, dst = os.path.join(ROOT, n), os.path.join(d, n)
        if os.path.isfile(src):
            os.makedirs(os.path.dirname(dst), exist_ok=True)
            shutil.copy2(src, dst)
    os.makedirs(os.path.join(d, "bin"))
    os.symlink(os.path.abspath(fsweep), os.path.join(d, "bin", "fsweep"))
    # build/release/bin: fsweep and the executables beside it (fsweep_bench), as the build has them.
    bin_dir = os.path.join(d, "build", "release", "bin")
    os.makedirs(bin_dir)
    os.symlink(os.path.abspath(fsweep), os.path.join(bin_dir, "fsweep"))
    beside = os.path.dirname(os.path.abspath(fsweep))
    for name in os.listdir(beside):
        path = os.path.join(beside, name)
        if name != "fsweep" and os.path.isfile(path) and os.access(path, os.X_OK):
            os.symlink(path, os.path.join(bin_dir, name))
    return d


def output_matches(expected, output):
    """True when every line of `expected` (ends trimmed) appears in `output` in order; '...'
    matches any number of lines."""
    got = [line.rstrip() for line in output.split("\n")]
    pos = 0
    for want in (line.rstrip() for line in expected.split("\n")):
        if want.strip() == "..." or not want.strip():
            continue
        while pos < len(got) and got[pos].strip() != want.strip():
            pos += 1
        if pos == len(got):
            return False, want
        pos += 1
    return True, ""


def check_page(page, fsweep, work, long):
    """(problems, blocks run, seconds) of one page."""
    start = time.time()
    blocks = blocks_of(page)
    problems, ran = [], 0
    scratch = None
    last_output = None
    env = dict(os.environ)
    for b in blocks:
        if b.mark == "skip":
            if not b.reason:
                problems.append(f"{b.where()}: a skip mark needs a reason (<!-- docs: skip: REASON -->)")
            continue
        if b.lang == "sh":
            if b.mark == "long" and not long:
                last_output = None
                continue
            if scratch is None:
                scratch = scratch_copy(work, page, fsweep)
                env["PATH"] = os.path.join(scratch, "bin") + os.pathsep + env.get("PATH", "")
            ran += 1
            try:
                r = subprocess.run(["bash", "-e", "-o", "pipefail", "-c", b.text], cwd=scratch, env=env,
                                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                   timeout=LONG_TIMEOUT_S if b.mark == "long" else SHORT_TIMEOUT_S)
                last_output = r.stdout
                if r.returncode != 0:
                    tail = "\n".join(r.stdout.rstrip().split("\n")[-15:])
                    problems.append(f"{b.where()}: exited {r.returncode}:\n{b.text}\n--- output (end):\n{tail}")
            except subprocess.TimeoutExpired:
                problems.append(f"{b.where()}: did not finish in its time limit")
                last_output = None
        elif b.lang == "json":
            try:
                value = json.loads(b.text)
            except json.JSONDecodeError as e:
                problems.append(f"{b.where()}: not valid JSON: {e}")
                continue
            if isinstance(value, dict) and "schema_version" in value:
                if scratch is None:
                    scratch = scratch_copy(work, page, fsweep)
                    env["PATH"] = os.path.join(scratch, "bin") + os.pathsep + env.get("PATH", "")
                path = os.path.join(scratch, "docs_sweep.json")
                with open(path, "w", encoding="utf-8") as f:
                    f.write(b.text)
                r = subprocess.run([fsweep, "expand", path, "--limit", "1"], cwd=scratch, stdout=subprocess.PIPE,
                                   stderr=subprocess.STDOUT, text=True, timeout=SHORT_TIMEOUT_S)
                if r.returncode != 0:
                    problems.append(f"{b.where()}: the sweep does not pass fsweep expand:\n{r.stdout[-2000:]}")
        elif b.mark == "output":
            if last_output is None:
                if long or not any(x.mark == "long" for x in blocks):
                    problems.append(f"{b.where()}: an output block without a ```sh block run before it")
                continue
            ok, missing = output_matches(b.text, last_output)
            if not ok:
                problems.append(f"{b.where()}: the output shown is not what the command printed; not found: "
                                f"{missing!r}\n--- printed:\n{last_output[-3000:]}")
    return problems, ran, time.time() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("fsweep", help="the fsweep executable to run the commands with")
    parser.add_argument("--long", action="store_true", help="also the blocks marked long")
    parser.add_argument("--page", action="append", help="only this page (repeat for several)")
    parser.add_argument("--work", help="scratch directory (default: fsweep-docs-work in the temp directory)")
    parser.add_argument("--jobs", type=int, default=2, help="pages checked at once (default 2)")
    args = parser.parse_args()
    work = os.path.abspath(args.work or os.path.join(tempfile.gettempdir(), "fsweep-docs-work"))
    os.makedirs(work, exist_ok=True)
    chosen = args.page or pages()
    failures = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        results = {p: pool.submit(check_page, p, args.fsweep, work, args.long) for p in chosen}
        for page in chosen:
            problems, ran, seconds = results[page].result()
            print(f"{page}: {ran} command blocks, {len(problems)} problems, {seconds:.1f} s")
            failures += problems
    for p in failures:
        print(f"FAIL {p}\n")
    # The first line of each problem again, last, for logs that keep only their end.
    for p in failures:
        print(f"FAIL {p.splitlines()[0][:300]}")
    print(f"check_docs.py: {len(chosen)} pages, {len(failures)} problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
