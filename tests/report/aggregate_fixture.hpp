#pragma once
// A small sweep output directory in the runner's layout (sweep_runner.hpp), with hand-computed
// expectations in test_aggregate.cpp. Three configurations, interleaved:
//   config 0: energy_aware w1=10 on free space, seeds 1..4 (distances 1, 2, 3, 4)
//   config 1: energy_aware w1=20 on free space, seeds 1..2
//   config 2: closest_frontier (no w1) on rooms, one run that never moved and failed
// Progress is sampled every 0.75 m plus each run's final sample; run a2 ends on the grid (3 m),
// the others off it; progress.csv ends with the rows of a run without a runs.csv row (torn).

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace fsweep::testing {

inline const char* const kRunsCsv =
    "run_index,run_key,map_class,map,strategy,strategy.w1,seed,end_reason,end_detail,distance_m,energy,"
    "recharges,"
    "distance_to_final_coverage_m,area_per_metre,coverage,optimal_distance_m,competitive_ratio\n"
    "0,00000000000000a0,free,\"free:w=10,h=10,seed=0\",energy_aware,10,1,complete,,1,10,0,0.5,22,1,2,0.5\n"
    "1,00000000000000b0,free,\"free:w=10,h=10,seed=0\",energy_aware,20,1,stuck,,1.5,50,1,1.5,6,0.8,2,0.75\n"
    "2,00000000000000a1,free,\"free:w=10,h=10,seed=0\",energy_aware,10,2,complete,,2,20,0,2,16,1,2,1\n"
    "3,00000000000000c0,rooms,\"rooms:w=10,h=10,door=2,seed=1\",closest_frontier,,1,error,"
    "\"planner failed, \"\"dock\"\" unreachable\",0,25,0,0,0,0.2,,\n"
    "4,00000000000000a2,free,\"free:w=10,h=10,seed=7\",energy_aware,10,3,range_limited,,3,30,1,3,11."
    "666666666666666,"
    "0.5,2,1.5\n"
    "5,00000000000000b1,free,\"free:w=10,h=10,seed=0\",energy_aware,20,2,complete,,2.5,10,0,2.5,5.6,1,2,1."
    "25\n"
    "6,00000000000000a3,free,\"free:w=10,h=10,seed=0\",energy_aware,10,4,complete,,4,40,0,3.5,12.5,1,2,2\n";

inline const char* const kProgressCsv =
    "run_index,run_key,distance_m,explored_area_m2,coverage,energy\n"
    "0,00000000000000a0,0,10,0.2,0\n"
    "0,00000000000000a0,0.75,20,0.4,7.5\n"
    "0,00000000000000a0,1,22,1,10\n"
    "1,00000000000000b0,0,5,0.1,0\n"
    "1,00000000000000b0,0.75,8,0.5,25\n"
    "1,00000000000000b0,1.5,9,0.8,50\n"
    "2,00000000000000a1,0,10,0.2,0\n"
    "2,00000000000000a1,0.75,25,0.5,7.5\n"
    "2,00000000000000a1,1.5,30,0.9,15\n"
    "2,00000000000000a1,2,32,1,20\n"
    "3,00000000000000c0,0,3,0.2,0\n"
    "4,00000000000000a2,0,10,0.2,0\n"
    "4,00000000000000a2,0.75,20,0.3,7.5\n"
    "4,00000000000000a2,1.5,30,0.4,15\n"
    "4,00000000000000a2,2.25,34,0.45,22.5\n"
    "4,00000000000000a2,3,35,0.5,30\n"
    "5,00000000000000b1,0,5,0.1,0\n"
    "5,00000000000000b1,0.75,9,0.4,3\n"
    "5,00000000000000b1,1.5,12,0.7,6\n"
    "5,00000000000000b1,2.25,13,0.9,9\n"
    "5,00000000000000b1,2.5,14,1,10\n"
    "6,00000000000000a3,0,10,0.2,0\n"
    "6,00000000000000a3,0.75,15,0.3,7.5\n"
    "6,00000000000000a3,1.5,25,0.5,15\n"
    "6,00000000000000a3,2.25,35,0.7,22.5\n"
    "6,00000000000000a3,3,45,0.9,30\n"
    "6,00000000000000a3,3.75,48,0.95,37.5\n"
    "6,00000000000000a3,4,50,1,40\n"
    "7,00000000000000d0,0,10,0.2,0\n"
    "7,00000000000000d0,0.75,99,0.9,7.5\n";

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f << text;
}

/// A fresh directory under the system temp dir holding the fixture's runs.csv and progress.csv.
inline std::filesystem::path make_sweep_dir(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("fsweep_aggregate_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  write_text(dir / "runs.csv", kRunsCsv);
  write_text(dir / "progress.csv", kProgressCsv);
  return dir;
}

}  // namespace fsweep::testing
