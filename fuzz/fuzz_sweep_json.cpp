// Fuzz target: a sweep file, read as `fsweep expand/run` read it (SweepPlan::from_file: JSON,
// validation, maps loaded), then the first runs resolved (spec and run key) as a run would.
#include <algorithm>
#include <cstdint>

#include "fuzz_support.hpp"
#include "sweep/sweep_plan.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fsweep;
  const std::string path = fuzz::write_scratch("sweep.json", fuzz::as_text(data, size));
  fuzz::accept_clear_errors([&] {
    const SweepPlan plan = SweepPlan::from_file(path);
    const std::uint64_t n = std::min<std::uint64_t>(plan.run_count(), 3);
    for (std::uint64_t i = 0; i < n; ++i) (void)plan.run(i);
    if (plan.run_count() > 3) (void)plan.run(plan.run_count() - 1);
  });
  return 0;
}
