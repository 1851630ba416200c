// Fuzz target: text grid maps: the MovingAI `.map` loader and the ASCII map parser, each given
// the input.
#include <cstdint>

#include "fuzz_support.hpp"
#include "world/map_loaders.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fsweep;
  const std::string_view text = fuzz::as_text(data, size);
  const std::string path = fuzz::write_scratch("grid.map", text);
  fuzz::accept_clear_errors([&] { (void)load_movingai_map(path); });
  fuzz::accept_clear_errors([&] { (void)parse_ascii_map(std::string(text)); });
  return 0;
}
