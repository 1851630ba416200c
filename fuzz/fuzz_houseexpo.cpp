// Fuzz target: a HouseExpo floor plan (JSON), drawn at HouseExpo's 0.04 m and at 0.25 m.
#include <cstdint>

#include "fuzz_support.hpp"
#include "world/map_loaders.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fsweep;
  const std::string path = fuzz::write_scratch("plan.json", fuzz::as_text(data, size));
  fuzz::accept_clear_errors([&] { (void)load_houseexpo(path); });
  fuzz::accept_clear_errors([&] { (void)load_houseexpo(path, 0.25); });
  return 0;
}
