/// @file sweep_json_reader.cpp
/// parse_sweep_json: nlohmann's parser with a callback that finds duplicate keys and stops at
/// kMaxSweepNesting, and its exceptions turned into messages naming the file, line and column.

#include "sweep/sweep_json_reader.hpp"

#include <algorithm>
#include <memory>
#include <set>

#include "core/config_error.hpp"
#include "core/json_text.hpp"

namespace fsweep {
inline namespace sweep {
namespace {

using nlohmann::json;

/// JSON paths in messages are cut here (keys may be long).
constexpr std::size_t kMaxPathText = 160;

/// Thrown by the parse callback when an array or object opens deeper than kMaxSweepNesting.
struct NestingTooDeep {
  std::string path;
};

/// Duplicate keys of one object, found while parsing (nlohmann keeps only the last), and the
/// JSON path of the value being parsed.
class DuplicateKeyFinder {
 public:
  bool operator()(json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (stack_.size() + 1 > static_cast<std::size_t>(kMaxSweepNesting)) throw NestingTooDeep{path()};
        stack_.push_back(Frame{event == json::parse_event_t::object_start, {}, {}, 0});
        break;
      case json::parse_event_t::key: {
        Frame& top = stack_.back();
        top.key = parsed.get<std::string>();
        if (!top.keys.insert(top.key).second) {
          problems_.push_back(path() + ": duplicate key '" + top.key +
                              "'; allowed: each key once (JSON keeps only "
                              "the last)");
        }
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        stack_.pop_back();
        element_done();
        break;
      case json::parse_event_t::value:
        element_done();
        break;
    }
    return true;
  }
  [[nodiscard]] const std::vector<std::string>& problems() const { return problems_; }
  /// The JSON path of the value being parsed ("/" at the top), cut after kMaxPathText characters.
  [[nodiscard]] std::string path() const {
    std::string p;
    for (const auto& f : stack_) {
      p += "/" + (f.object ? f.key : std::to_string(f.index));
      if (p.size() > kMaxPathText) return p.substr(0, kMaxPathText) + "...";
    }
    return p.empty() ? "/" : p;
  }

 private:
  struct Frame {
    bool object;
    std::set<std::string> keys;
    std::string key;
    std::size_t index;
  };
  void element_done() {
    if (!stack_.empty() && !stack_.back().object) ++stack_.back().index;
  }
  std::vector<Frame> stack_;
  std::vector<std::string> problems_;
};

/// `s` cut to `n` characters for messages.
std::string cut(const std::string& s, std::size_t n) { return s.size() > n ? s.substr(0, n) + "..." : s; }

}  // namespace

SweepJson parse_sweep_json(const std::string& text, const std::string& path) {
  auto finder = std::make_shared<DuplicateKeyFinder>();
  SweepJson out;
  try {
    out.value = json::parse(
        text, [finder](int /*depth*/, json::parse_event_t e, json& p) { return (*finder)(e, p); });
  } catch (const NestingTooDeep& e) {
    throw ConfigError(text_position(path, text, first_too_deep_opening(text, kMaxSweepNesting)),
                      e.path + ": arrays and objects are nested more than " +
                          std::to_string(kMaxSweepNesting) + " levels deep; allowed: at most " +
                          std::to_string(kMaxSweepNesting) + " levels");
  } catch (const json::parse_error& e) {
    // e.byte: 1-based position of the offending character.
    std::string detail = e.what();
    if (const std::size_t colon = detail.find(": ", detail.find("column")); colon != std::string::npos) {
      detail = detail.substr(colon + 2);
    }
    throw ConfigError(text_position(path, text, e.byte == 0 ? 0 : e.byte - 1),
                      "invalid JSON: " + cut(detail, 200));
  } catch (const json::out_of_range&) {
    // 406: a number beyond the range of a double; nlohmann names neither the place nor the path.
    const auto [offset, number] = first_overflowing_number(text);
    throw ConfigError(text_position(path, text, offset),
                      finder->path() + ": number " + cut(number, 40) +
                          " is out of range; allowed: numbers of magnitude below 1.8e308 (a double)");
  }
  out.problems = finder->problems();
  return out;
}

}  // namespace sweep
}  // namespace fsweep
