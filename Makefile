# The two commands of the README:
#   make run       - install what is missing, build the fsweep executable (Release), run
#                    sweeps/default.json and plot it
#   make test      - install what is missing, build, run the whole test suite (unit tests, the
#                    single-node Slurm integration test, and a sanitizer pass that also fuzzes
#                    every input parser for a few seconds)
#   make fuzz      - fuzz every input parser longer (FUZZ_SECONDS each, default 300; fuzz/README.md)
#   make docs-long - run the command blocks of the docs marked long too (docs/dev/docs-tests.md)
#   make test-long - the long property tests (ctest label long; also in the nightly job)
#   make tidy      - clang-tidy on src/ (.clang-tidy; every finding fails; also in the nightly job)
#   make install PREFIX=DIR - install fsweep, its scripts, bash completion and docs (docs/install.md)
# and the nightly regression job (docs/running.md, "Nightly regression checks"):
#   make nightly   - build, run sweeps/nightly.json and the micro-benchmarks into results/nightly/,
#                    compare them with results/baseline/nightly/ (exit 1 on a regression)
#   make baseline  - the same suite and benchmarks, copied over results/baseline/nightly/
.PHONY: run test build install bench fuzz docs-long test-long tidy nightly baseline clean

FSWEEP := build/release/bin/fsweep

run:
	@scripts/bootstrap release fsweep
	@$(FSWEEP) run sweeps/default.json
	@$(FSWEEP) plot results/default >/dev/null && echo "plots in results/default/plots/"

build:
	@scripts/bootstrap release

# make install PREFIX=DIR (default /usr/local): fsweep, its scripts, bash completion and docs.
PREFIX ?= /usr/local
install:
	@scripts/bootstrap release fsweep
	cmake --install build/release --prefix "$(PREFIX)"

# The GoogleTest suites and fuzz replays run once, sanitized (label unit-also-sanitized: tests/CMakeLists.txt).
test:
	@scripts/bootstrap release fsweep
	cd build/release && ctest --output-on-failure -j 2 -L unit -LE also-sanitized || { ../../scripts/ctest-failures .; exit 1; }
	@# The Slurm test mostly waits on its daemons (8 of its 31 s on a CPU), so it runs while the
	@# sanitizer tree builds; its output comes when both are done.
	@(cd build/release && ctest --output-on-failure -L slurm > slurm-test.log 2>&1; echo $$? > slurm-test.rc) & \
	  scripts/bootstrap asan; built=$$?; wait; cat build/release/slurm-test.log; \
	  [ "$$(cat build/release/slurm-test.rc)" = 0 ] || { scripts/ctest-failures build/release; exit 1; }; \
	  exit $$built
	cd build/asan && ctest --output-on-failure -j 2 -L sanitize || { ../../scripts/ctest-failures .; exit 1; }

FUZZ_SECONDS ?= 300
fuzz:
	@scripts/bootstrap asan
	scripts/fuzz $(FUZZ_SECONDS)

tidy:
	@scripts/bootstrap tidy

docs-long: build
	cd build/release && ctest --output-on-failure -L docs-long

test-long: build
	cd build/release && ctest --output-on-failure -L '^long$$'

bench: build
	build/release/bin/fsweep_bench

nightly: build
	@scripts/bootstrap slurm
	scripts/nightly

baseline: build
	scripts/nightly --baseline

clean:
	rm -rf build
