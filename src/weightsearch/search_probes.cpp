#include "weightsearch/search_probes.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/json_text.hpp"

namespace fsweep {
inline namespace weightsearch {

using nlohmann::json;

std::vector<SearchProbeLog::Probe> SearchProbeLog::read(const std::string& path, const std::string& key,
                                                        int weights) {
  std::vector<Probe> out;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    try {
      if (in.eof()) throw std::runtime_error("no newline");
      const json j = parse_json_bounded(line, path);
      if (j.at("key").get<std::string>() != key) continue;
      const auto at = j.at("at").get<std::vector<int>>();
      if (at.size() != static_cast<std::size_t>(weights))
        throw std::runtime_error("not a point of this search");
      Probe p;
      for (std::size_t k = 0; k < at.size(); ++k) p.at[k] = at[k];
      const json& objective = j.at("objective");
      p.objective = objective.is_null() ? std::numeric_limits<double>::quiet_NaN() : objective.get<double>();
      out.push_back(p);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "fsweep: %s:%zu: %s; this probe is run again\n", path.c_str(), number, e.what());
    }
  }
  return out;
}

void SearchProbeLog::append(const std::string& key, const Point& at, int weights, double objective) {
  const json line{{"key", key},
                  {"at", std::vector<int>(at.begin(), at.begin() + weights)},
                  {"objective", std::isnan(objective) ? json(nullptr) : json(objective)}};
  file_.write(line.dump() + '\n');
}

}  // namespace weightsearch
}  // namespace fsweep
