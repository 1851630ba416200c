# The two commands of the README:
#   make run   - install what is missing, build (Release), run sweeps/default.json and plot it
#   make test  - install what is missing, build, run the whole test suite (plus a sanitizer pass)
.PHONY: run test build bench clean

FSWEEP := build/release/bin/fsweep

run: build
	@$(FSWEEP) run sweeps/default.json
	@$(FSWEEP) plot results/default >/dev/null && echo "plots in results/default/plots/"

build:
	@scripts/bootstrap release

test:
	@scripts/bootstrap release
	cd build/release && ctest --output-on-failure -j 2 -L unit
	@scripts/bootstrap asan
	cd build/asan && ctest --output-on-failure -j 2 -L sanitize

bench: build
	build/release/bin/fsweep_bench

clean:
	rm -rf build
