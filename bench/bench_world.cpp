/// @file bench_world.cpp
/// Micro-benchmarks of the per-step world updates on a seeded 200 x 200 map (1 m cells, 15%
/// obstacle cells; generated here so the numbers do not depend on the map generators):
///
/// - `BM_SensorSetup/range:<cells>`: constructing a Sensor (its O(r^2) tables).
/// - `BM_SensorScan/range:<cells>`: one sensor scan into unexplored space (fresh KnownMap),
///   from 256 fixed free cells in turn; `revealed_per_scan` cells revealed on average.
/// - `BM_SensorScanBuilding/range:<cells>`: the same in a partly explored building (a
///   generated office of 400 x 400 cells, its left half known; scans from 256 free cells).
/// - `BM_SensorScanKnown/range:<cells>`: one scan where every cell in range is already known.
/// - `BM_SensorScanSight/range:<cells>`: BM_SensorScan with a SightTable whose rows for the 256
///   cells are filled (what a weight search's scans from cells scanned before cost).
/// - `BM_BeamScan/beams:<n>/range_m:<m>`: one scan of the beam model (n beams over 270 degrees
///   for 1080, else 180) in a 60 m x 60 m office at 5 cm per cell (1200 x 1200 cells), fresh
///   KnownMap, from 256 free cells; `BM_GridScanOffice/range_m:<m>`: the grid model there.
/// - `BM_FrontierUpdate`: one incremental FrontierMap::update after a scan, cycling through 16
///   consecutive steps of a greedy exploration (after 100 warm-up steps).
/// - `BM_FrontierRebuild`: a full FrontierMap::rebuild on the same 16 maps.
/// - `BM_FrontierClusters/corner_cutting:<0|1>`, `BM_FrontierClustersLargeMap`,
///   `BM_FrontierCells`: frontier clustering (pieces of at most 10 m) and the frontier cell
///   list after 100 exploration steps (660 frontier cells).
///
/// Inputs are fixed (seeded), and each benchmark cycles through many more iterations than it
/// has inputs, so every run measures the same mix.

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

#include "core/random.hpp"
#include "world/frontiers.hpp"
#include "world/known_map.hpp"
#include "world/map_spec.hpp"
#include "world/sensor.hpp"
#include "world/world_map.hpp"

namespace fsweep {
namespace {

constexpr int kSide = 200;  // map side (cells)

/// 200 x 200 cells at 1 m, obstacle cells with probability `p` (seeded), start free.
WorldMap bench_world(double p) {
  WorldMap map;
  map.occupied = Grid<std::uint8_t>(kSide, kSide, 0);
  map.resolution_m = 1.0;
  Rng rng = make_rng(42, "bench-map");
  for (int i = 0; i < map.occupied.size(); ++i) map.occupied[i] = uniform01(rng) < p ? 1 : 0;
  map.start = Cell{kSide / 2, kSide / 2};
  map.occupied.at(map.start) = 0;
  return map;
}

/// `n` free cells at least `margin` cells from the edge (seeded).
std::vector<Cell> free_cells(const WorldMap& map, int n, int margin) {
  std::vector<Cell> out;
  Rng rng = make_rng(7, "bench-cells");
  const auto span_x = static_cast<std::uint64_t>(map.width() - 2 * margin);
  const auto span_y = static_cast<std::uint64_t>(map.height() - 2 * margin);
  while (static_cast<int>(out.size()) < n) {
    const Cell c{margin + static_cast<int>(uniform_below(rng, span_x)),
                 margin + static_cast<int>(uniform_below(rng, span_y))};
    if (map.is_free(c)) out.push_back(c);
  }
  return out;
}

SensorParams sensor_params(double range_m) {
  SensorParams p;
  p.range_m = range_m;
  return p;
}

/// Constructing a sensor with a range of `range` cells, 360 degree field of view.
void BM_SensorSetup(benchmark::State& state) {  // NOLINT(readability-identifier-naming)
  const SensorParams params = sensor_params(static_cast<double>(state.range(0)));
  for (auto _ : state) {
    Sensor sensor(params, 1.0);
    benchmark::DoNotOptimize(sensor.range_cells());
  }
}
BENCHMARK(BM_SensorSetup)->ArgName("range")->Arg(20)->Arg(100)->Arg(200)->Unit(benchmark::kMillisecond);

/// One scan of `map` from each cell of `at` in turn, each into a copy of `start`, with a sensor
/// of `params`. The copies are prepared in batches with the timer paused, so the pause cost is
/// amortised over a batch and the map copy is not timed.
void scan_from(benchmark::State& state, const WorldMap& map, const KnownMap& start,
               const std::vector<Cell>& at, const SensorParams& params, SightTable* sight = nullptr) {
  Sensor sensor(params, map.resolution_m);
  constexpr std::size_t kBatch = 64;
  std::vector<KnownMap> pool(kBatch, start);
  Rng rng = make_rng(1, "sensor");
  std::size_t used = 0;
  std::size_t next = 0;
  std::int64_t revealed = 0;
  for (auto _ : state) {
    if (used == kBatch) {
      state.PauseTiming();
      for (KnownMap& k : pool) k = start;
      used = 0;
      state.ResumeTiming();
    }
    const auto cells = sensor.scan(map, pool[used++], at[next++ % at.size()], 0.0, rng, nullptr, sight);
    revealed += static_cast<std::int64_t>(cells.size());
    benchmark::DoNotOptimize(cells.data());
  }
  state.counters["revealed_per_scan"] =
      benchmark::Counter(static_cast<double>(revealed), benchmark::Counter::kAvgIterations);
}

/// One scan from a fresh (all unknown) KnownMap: the full cost of a scan into unexplored space.
void BM_SensorScan(benchmark::State& state) {  // NOLINT(readability-identifier-naming)
  const WorldMap map = bench_world(0.15);
  scan_from(state, map, KnownMap(kSide, kSide, map.resolution_m), free_cells(map, 256, 0),
            sensor_params(static_cast<double>(state.range(0))));
}
BENCHMARK(BM_SensorScan)->ArgName("range")->Arg(10)->Arg(20)->Arg(30)->Arg(100)->Arg(200);

/// BM_SensorScan reading a SightTable filled from the same cells first.
void BM_SensorScanSight(benchmark::State& state) {  // NOLINT(readability-identifier-naming)
  const WorldMap map = bench_world(0.15);
  const SensorParams params = sensor_params(static_cast<double>(state.range(0)));
  const std::vector<Cell> at = free_cells(map, 256, 0);
  Sensor sensor(params, map.resolution_m);
  const std::unique_ptr<SightTable> sight = sensor.sight_table(map);
  if (sight == nullptr) {
    state.SkipWithError("no sight table at this range and map size");
    return;
  }
  Rng rng = make_rng(1, "sensor");
  for (const Cell c : at) {
    KnownMap fresh(kSide, kSide, map.resolution_m);
    (void)sensor.scan(map, fresh, c, 0.0, rng, nullptr, sight.get());
  }
  scan_from(state, map, KnownMap(kSide, kSide, map.resolution_m), at, params, sight.get());
}
BENCHMARK(BM_SensorScanSight)->ArgName("range")->Arg(10)->Arg(30)->Arg(100);

/// One scan in a partly explored building: a generated office (400 x 400 cells: rooms at least
/// 40 cells deep, corridors 20 wide, walls 3 thick, doors 16 wide, e.g. 20 m x 20 m at 5 cm),
/// every cell of its left half known, scans from 256 free cells anywhere.
void BM_SensorScanBuilding(benchmark::State& state) {  // NOLINT(readability-identifier-naming)
  const WorldMap map = load_map_spec("office:w=400,h=400,min_room=40,corridor=20,wall=3,door=16,seed=3");
  KnownMap known(map.width(), map.height(), map.resolution_m);
  for (int i = 0; i < known.size(); ++i) {
    if (known.cell(i).x < map.width() / 2) known.reveal(i, map.occupied[i] != 0);
  }
  scan_from(state, map, known, free_cells(map, 256, 0), sensor_params(static_cast<double>(state.range(0))));
}
BENCHMARK(BM_SensorScanBuilding)->ArgName("range")->Arg(20)->Arg(100)->Arg(200);

/// A 60 m x 60 m office at 5 cm per cell: rooms at least 4 m, corridors 2 m, walls 15 cm,
/// doors 1 m.
WorldMap fine_office() {
  return load_map_spec("office:w=1200,h=1200,min_room=80,corridor=40,wall=3,door=20,seed=3,res=0.05");
}

/// One beam-model scan into unexplored space in fine_office(): 1080 beams over 270 degrees
/// (Hokuyo UTM-30LX) or 181 over 180 (SICK LMS 200); argument 1: range (m).
void BM_BeamScan(benchmark::State& state) {  // NOLINT(readability-identifier-naming)
  const WorldMap map = fine_office();
  SensorParams params = sensor_params(static_cast<double>(state.range(1)));
  params.model = SensorModel::Beams;
  params.beams = static_cast<int>(state.range(0));
  params.fov_deg = params.beams == 1080 ? 270.0 : 180.0;
  scan_from(state, map, KnownMap(map.width(), map.height(), map.resolution_m), free_cells(map, 256, 0),
            params);
}
BENCHMARK(BM_BeamScan)->ArgNames({"beams", "range_m"})->Args({1080, 30})->Args({181, 8})->Args({181, 30});

/// The grid model in the same office, same cells (argument: range in m; 30 m = 600 cells).
void BM_GridScanOffice(benchmark::State& state) {  // NOLINT(readability-identifier-naming)
  const WorldMap map = fine_office();
  scan_from(state, map, KnownMap(map.width(), map.height(), map.resolution_m), free_cells(map, 256, 0),
            sensor_params(static_cast<double>(state.range(0))));
}
BENCHMARK(BM_GridScanOffice)->ArgName("range_m")->Arg(8)->Arg(30);

/// One scan where every cell in range is already known (the skip path; robot standing still).
void BM_SensorScanKnown(benchmark::State& state) {  // NOLINT(readability-identifier-naming)
  const WorldMap map = bench_world(0.15);
  Sensor sensor(sensor_params(static_cast<double>(state.range(0))), map.resolution_m);
  KnownMap known(kSide, kSide, map.resolution_m);
  for (int i = 0; i < known.size(); ++i) known.reveal(i, map.occupied[i] != 0);
  const std::vector<Cell> at = free_cells(map, 256, 0);
  Rng rng = make_rng(1, "sensor");
  std::size_t next = 0;
  for (auto _ : state) {
    const auto cells = sensor.scan(map, known, at[next++ % at.size()], 0.0, rng);
    benchmark::DoNotOptimize(cells.data());
  }
}
BENCHMARK(BM_SensorScanKnown)->ArgName("range")->Arg(10)->Arg(100);

/// Snapshots of a greedy exploration (scan, go to the nearest frontier cell, repeat) on the
/// bench map: the map after a scan, the cells that scan revealed, the frontiers before it.
struct Snapshot {
  KnownMap known;
  std::vector<int> revealed;
  FrontierMap before;
};

int nearest_frontier(const KnownMap& known, const FrontierMap& frontiers, Cell from) {
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(known.size()), 0);
  std::deque<Cell> queue{from};
  seen[static_cast<std::size_t>(known.index(from))] = 1;
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    if (frontiers.is_frontier(known.index(c))) return known.index(c);
    for (const Cell d : kDirections) {
      const Cell n{c.x + d.x, c.y + d.y};
      if (!known.is_free(n) || seen[static_cast<std::size_t>(known.index(n))] != 0) continue;
      seen[static_cast<std::size_t>(known.index(n))] = 1;
      queue.push_back(n);
    }
  }
  return frontiers.count() > 0 ? frontiers.cells().front() : -1;
}

/// Runs `warmup` steps, then records `count` snapshots (range 10 cells).
std::vector<Snapshot> exploration_snapshots(int warmup, int count) {
  const WorldMap map = bench_world(0.15);
  Sensor sensor(sensor_params(10.0), map.resolution_m);
  KnownMap known(kSide, kSide, map.resolution_m);
  FrontierMap frontiers(known);
  Rng rng = make_rng(1, "sensor");
  Cell at = map.start;
  std::vector<Snapshot> out;
  for (int step = 0; step < warmup + count; ++step) {
    const FrontierMap before = frontiers;
    const auto revealed = sensor.scan(map, known, at, 0.0, rng);
    frontiers.update(known, revealed);
    if (step >= warmup) out.push_back(Snapshot{known, {revealed.begin(), revealed.end()}, before});
    const int target = nearest_frontier(known, frontiers, at);
    if (target < 0) break;
    at = known.cell(target);
  }
  return out;
}

/// FrontierMap::update after one scan step of an exploration (cycling through 16 steps).
/// update() is idempotent for a given (known, revealed) pair and recomputes the same cells each
/// time, so repeating it on the same FrontierMap costs what the first call cost.
void BM_FrontierUpdate(benchmark::State& state) {  // NOLINT(readability-identifier-naming)
  std::vector<Snapshot> snaps = exploration_snapshots(100, 16);
  std::size_t next = 0;
  std::int64_t revealed = 0;
  for (auto _ : state) {
    Snapshot& s = snaps[next++ % snaps.size()];
    s.before.update(s.known, s.revealed);
    revealed += static_cast<std::int64_t>(s.revealed.size());
    benchmark::DoNotOptimize(s.before.count());
  }
  state.counters["revealed_per_update"] =
      benchmark::Counter(static_cast<double>(revealed), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_FrontierUpdate);

/// Full rebuild on the same maps, for comparison with the incremental update.
void BM_FrontierRebuild(benchmark::State& state) {  // NOLINT(readability-identifier-naming)
  std::vector<Snapshot> snaps = exploration_snapshots(100, 16);
  FrontierMap frontiers;
  std::size_t next = 0;
  for (auto _ : state) {
    frontiers.rebuild(snaps[next++ % snaps.size()].known);
    benchmark::DoNotOptimize(frontiers.count());
  }
}
BENCHMARK(BM_FrontierRebuild);

/// FrontierMap::clusters (pieces of at most 10 m) after 100 exploration steps. Argument:
/// allow_corner_cutting (0 or 1).
void BM_FrontierClusters(benchmark::State& state) {  // NOLINT(readability-identifier-naming)
  const std::vector<Snapshot> snaps = exploration_snapshots(100, 1);
  const FrontierMap frontiers(snaps.front().known);
  const bool corner_cutting = state.range(0) != 0;
  std::int64_t clusters = 0;
  for (auto _ : state) {
    const auto result = frontiers.clusters(snaps.front().known, 10.0, corner_cutting);
    clusters += static_cast<std::int64_t>(result.size());
    benchmark::DoNotOptimize(result.data());
  }
  state.counters["frontier_cells"] = frontiers.count();
  state.counters["clusters"] =
      benchmark::Counter(static_cast<double>(clusters), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_FrontierClusters)->ArgName("corner_cutting")->Arg(0)->Arg(1);

/// The same frontier on a 1000 x 1000 map: the snapshot pasted into a corner, every other cell
/// known occupied. Clustering should cost the same as above (O(frontier cells), not O(map)).
void BM_FrontierClustersLargeMap(benchmark::State& state) {  // NOLINT(readability-identifier-naming)
  constexpr int kLargeSide = 1000;
  const std::vector<Snapshot> snaps = exploration_snapshots(100, 1);
  const KnownMap& small = snaps.front().known;
  KnownMap known(kLargeSide, kLargeSide, small.resolution_m());
  for (int y = 0; y < kLargeSide; ++y) {
    for (int x = 0; x < kLargeSide; ++x) {
      const Cell c{x, y};
      const CellState s = small.in_bounds(c) ? small.state(c) : CellState::Occupied;
      if (s != CellState::Unknown) known.reveal(known.index(c), s == CellState::Occupied);
    }
  }
  const FrontierMap frontiers(known);
  std::int64_t clusters = 0;
  for (auto _ : state) {
    const auto result = frontiers.clusters(known, 10.0, false);
    clusters += static_cast<std::int64_t>(result.size());
    benchmark::DoNotOptimize(result.data());
  }
  state.counters["frontier_cells"] = frontiers.count();
  state.counters["clusters"] =
      benchmark::Counter(static_cast<double>(clusters), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_FrontierClustersLargeMap);

/// FrontierMap::cells() on the same map.
void BM_FrontierCells(benchmark::State& state) {  // NOLINT(readability-identifier-naming)
  const std::vector<Snapshot> snaps = exploration_snapshots(100, 1);
  const FrontierMap frontiers(snaps.front().known);
  for (auto _ : state) {
    const auto cells = frontiers.cells();
    benchmark::DoNotOptimize(cells.data());
  }
  state.counters["frontier_cells"] = frontiers.count();
}
BENCHMARK(BM_FrontierCells);

}  // namespace
}  // namespace fsweep
