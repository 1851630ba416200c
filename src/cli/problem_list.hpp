#pragma once
/// @file problem_list.hpp
/// A list of problems as the commands print it: the first ones in full, the rest counted.

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace fsweep::cli {

/// Prints `problems` one a line, indented by two spaces: the first `listed` in full, then
/// "... and N more".
inline void print_problems(std::ostream& out, const std::vector<std::string>& problems,
                           std::size_t listed = 20) {
  for (std::size_t i = 0; i < problems.size() && i < listed; ++i) out << "  " << problems[i] << '\n';
  if (problems.size() > listed) out << "  ... and " << problems.size() - listed << " more\n";
}

}  // namespace fsweep::cli
