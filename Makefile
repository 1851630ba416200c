# The two commands of the README:
#   make run   - install what is missing, build (Release), run the default exploration
#   make test  - install what is missing, build, run the whole test suite (plus a sanitizer pass)
.PHONY: run test build bench clean

FSWEEP := build/release/bin/fsweep
OUT    := results/default

run: build
	@$(FSWEEP) sim --map "rooms:w=120,h=80,door=3,seed=4" --strategy energy_aware \
	  --param w1=10 --param w2=0 --param w3=9 --param w4=20 \
	  --robot sensor.range_m=10 --robot battery=1500 --out $(OUT)
	@echo "results: $(OUT)/run.csv, $(OUT)/progress.csv, picture: $(OUT)/trajectory.png"

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
