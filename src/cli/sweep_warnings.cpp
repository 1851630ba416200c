#include "cli/sweep_warnings.hpp"

#include <iostream>

#include "sweep/sweep_table.hpp"

namespace fsweep::cli {

void print_sweep_warnings(const SweepPlan& plan, const std::string& file) {
  for (const std::string& line : sweep_warnings(plan)) {
    std::cerr << "fsweep: warning: " << file << ": " << line << '\n';
  }
}

}  // namespace fsweep::cli
