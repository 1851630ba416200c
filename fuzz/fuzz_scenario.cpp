// Fuzz target: a MovingAI `.scen` file, loaded and (its first 16 queries) checked on a fixed
// 16x12 map, as `fsweep plan` and `plan-bench` do: queries naming cells outside the map or in
// a wall must be told apart, not crash.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "evaluation/scenario_check.hpp"
#include "fuzz_support.hpp"
#include "planners/registry.hpp"
#include "world/map_loaders.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fsweep;
  static const WorldMap map = parse_ascii_map(
      "................\n"
      "....#######.....\n"
      "..........#.....\n"
      "..........#.....\n"
      "...####...#.....\n"
      "......#.........\n"
      "......#....###..\n"
      "......#.........\n"
      "................\n"
      ".....#######....\n"
      "................\n"
      "................\n");
  const std::string path = fuzz::write_scratch("queries.scen", fuzz::as_text(data, size));
  fuzz::accept_clear_errors([&] {
    std::vector<ScenarioQuery> queries = load_scenario(path);
    queries.resize(std::min<std::size_t>(queries.size(), 16));
    const auto planner = make_planner("astar", nullptr, "fuzz");
    (void)check_scenario(map, queries, *planner);
  });
  return 0;
}
