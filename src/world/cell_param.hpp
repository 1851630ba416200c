#pragma once
/// @file cell_param.hpp
/// A declared parameter (core/params.hpp) that names a cell of the map, or "random" (a cell the
/// run draws from its seed), or null (none): a target_seeking strategy's `target`, the sim's
/// `stop_at_cell`.

#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/json_excerpt.hpp"
#include "core/params.hpp"
#include "world/grid.hpp"

namespace fsweep {
inline namespace world {

/// `v` as a cell when it is [x, y] with two integers in [0, INT_MAX], else nothing.
[[nodiscard]] inline std::optional<Cell> cell_from_json(const nlohmann::json& v) {
  const auto coordinate = [](const nlohmann::json& c) {
    return c.is_number_integer() && c.get<long long>() >= 0 &&
           c.get<long long>() <= std::numeric_limits<int>::max();
  };
  if (!v.is_array() || v.size() != 2 || !coordinate(v[0]) || !coordinate(v[1])) return std::nullopt;
  return Cell{v[0].get<int>(), v[1].get<int>()};
}

/// Declares parameter `name` of P: [x, y] into `cell`, "random" sets `random`, null (the default)
/// leaves both empty.
template <class P>
void declare_cell_or_random(ParamDecl<P>& d, std::string name, std::optional<Cell> P::*cell, bool P::*random,
                            std::string doc) {
  ParamSpec spec;
  spec.name = std::move(name);
  spec.type = ParamType::Custom;
  spec.nullable = true;
  spec.unit = "cells";
  spec.doc = std::move(doc);
  spec.allowed_text = "[x, y], two integers >= 0, or \"random\"";
  spec.custom_check = [](const nlohmann::json& v) -> std::vector<std::string> {
    if (v == nlohmann::json("random") || cell_from_json(v)) return {};
    return {"value " + json_excerpt(v) +
            " is not a cell; allowed: [x, y], two integers >= 0, \"random\", or null"};
  };
  d.custom(
      std::move(spec),
      [cell, random](P& p, const nlohmann::json& v) {
        p.*random = v == nlohmann::json("random");
        p.*cell = cell_from_json(v);
      },
      [cell, random](const P& p) {
        if (p.*random) return nlohmann::json("random");
        const std::optional<Cell>& c = p.*cell;
        return c ? nlohmann::json{c->x, c->y} : nlohmann::json();
      });
}

}  // namespace world
}  // namespace fsweep
