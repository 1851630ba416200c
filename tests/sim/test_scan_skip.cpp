// A scan whose range holds no unknown cell that a scan from a reachable cell could ever see is
// skipped (Sensor::scan's `observable`, RunSetup::observable): the skip must never change what is
// revealed. Checked on maps with buildings (street grids, rooms, random obstacles, offices, a MovingAI map),
// at every reachable cell in a seeded order, both corner rules and several ranges: the cells revealed, in
// order, and the known map equal those of scans without the skip.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "core/random.hpp"
#include "sim/run_setup.hpp"
#include "world/map_spec.hpp"
#include "world/sensor.hpp"

namespace fsweep {
namespace test_scan_skip {  // not anonymous: unity builds

TEST(ScanSkip, SkippingScansOfNeverSeenCellsRevealsTheSameCells) {
  int skipped = 0;
  int scans = 0;
  for (const std::string& spec :
       {std::string("manhattan:w=60,h=60,seed=2"), std::string("rooms:w=50,h=40,door=3,seed=5"),
        std::string("random:w=48,h=48,p=0.3,seed=4"), std::string("office:w=40,h=40,seed=3"),
        std::string(FSWEEP_TEST_DATA) + "/den312d.map"}) {
    const WorldMap map = load_map_spec(spec);
    for (const bool cut : {false, true}) {
      const Grid<std::uint8_t> reachable = reachable_free(map, map.start, cut);
      const Grid<std::uint8_t> observable = observable_cells(map, reachable);
      for (const double range : {1.5, 3.0, 7.0}) {
        SensorParams params;
        params.range_m = range;
        Sensor with(params, 1.0);
        Sensor without(params, 1.0);
        KnownMap a(map.width(), map.height(), 1.0);
        KnownMap b(map.width(), map.height(), 1.0);
        std::vector<int> cells;
        for (int i = 0; i < reachable.size(); ++i) {
          if (reachable[i] != 0) cells.push_back(i);
        }
        Rng order = make_rng(7, "order");
        std::shuffle(cells.begin(), cells.end(), order);
        cells.insert(cells.end(), cells.begin(), cells.end());  // a second round: mostly known
        Rng ra = make_rng(1, "sensor");
        Rng rb = make_rng(1, "sensor");
        for (const int i : cells) {
          const Cell at = reachable.cell(i);
          const std::vector<int> got = [&] {
            const auto s = with.scan(map, a, at, 0.0, ra, observable.data().data());
            return std::vector<int>(s.begin(), s.end());
          }();
          const auto s = without.scan(map, b, at, 0.0, rb);
          ASSERT_EQ(got, std::vector<int>(s.begin(), s.end()))
              << spec << " cut " << cut << " range " << range << " at (" << at.x << ", " << at.y << ")";
          ++scans;
          skipped += got.empty() ? 1 : 0;
        }
        ASSERT_TRUE(a == b) << spec;
      }
    }
  }
  EXPECT_GT(skipped, scans / 4) << "the maps should hold many scans with nothing left to see";
}

}  // namespace test_scan_skip
}  // namespace fsweep
