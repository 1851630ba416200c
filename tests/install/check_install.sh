#!/usr/bin/env bash
# cmake --install of a build tree into a fresh prefix, then fsweep run from there alone: its
# version, a small sweep, its plots drawn with the installed tools/plot.py (found beside the
# installed executable, not in the source tree), the bash completion and the help text.
#   check_install.sh BUILD_DIR WORK_DIR
set -euo pipefail
build=$1
work=$2
rm -rf "$work"
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >/dev/null
fsweep=$prefix/bin/fsweep
fail() { echo "FAIL: $*"; exit 1; }
"$fsweep" --version | head -1 | grep -q '^fsweep [0-9]' || fail "fsweep --version: $("$fsweep" --version)"
[ -x "$prefix/share/fsweep/tools/plot.py" ] || fail "no share/fsweep/tools/plot.py"
[ -s "$prefix/share/doc/fsweep/fsweep-help.txt" ] || fail "no help text"
grep -q "fsweep paired" "$prefix/share/doc/fsweep/fsweep-help.txt" || fail "the help text lacks fsweep paired"
bash -n "$prefix/share/bash-completion/completions/fsweep" || fail "the completion script does not parse"
# shellcheck disable=SC1091
words=$(bash -c "source '$prefix/share/bash-completion/completions/fsweep'; COMP_WORDS=(fsweep pai); COMP_CWORD=1; _fsweep; echo \${COMPREPLY[*]}")
[ "$words" = paired ] || fail "completion of 'fsweep pai' gave '$words'"
# A run from the prefix, in a directory of its own: the plots use the installed script.
mkdir -p "$work/run"
cd "$work/run"
cat > sweep.json <<'END'
{"schema_version": 1, "name": "installed", "maps": [{"generator": "rooms", "w": 30, "h": 24, "label": "rooms", "seeds": [1, 2]}],
 "strategies": [{"name": "closest_frontier", "label": "CF"}, {"name": "energy_aware", "label": "EA"}], "seed": 1}
END
"$fsweep" run sweep.json --quiet >/dev/null
"$fsweep" paired results/installed >/dev/null
[ -s results/installed/paired.csv ] || fail "no paired.csv"
if /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
  mkdir -p fakebin
  printf '#!/bin/sh\n[ "$1" = -c ] && exit 0\nexit 3\n' > fakebin/python3
  chmod +x fakebin/python3
  out=$(PATH="$PWD/fakebin:$PATH" "$fsweep" plot results/installed 2>&1 || true)
  case "$out" in
    *"$prefix/share/fsweep/tools/plot.py failed"*) ;;
    *) fail "fsweep plot did not run the installed script: $out" ;;
  esac
  "$fsweep" plot results/installed >/dev/null
  [ -s results/installed/plots/progress.png ] || fail "no progress.png"
fi
echo "PASS: installed into $prefix and ran from there"
