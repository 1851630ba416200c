/// @file register_all.cpp
/// The one place where strategies are registered.

#include <map>
#include <nlohmann/json.hpp>

#include "core/config_error.hpp"
#include "strategies/energy_aware.hpp"
#include "strategies/gbl.hpp"
#include "strategies/mcdm.hpp"
#include "strategies/orientation.hpp"
#include "strategies/random_frontier.hpp"
#include "strategies/registry.hpp"
#include "strategies/target_seeking.hpp"
#include "strategies/widest_frontier.hpp"

namespace fsweep {
inline namespace strategies {
namespace {

using Made = std::unique_ptr<Strategy>;

/// The registry and, by the same names, the traits (strategies whose traits are not given have
/// the defaults: not seeded, not linear-scored).
struct StrategyCatalog {
  StrategyRegistry registry{"strategy"};
  std::map<std::string, StrategyTraits, std::less<>> traits;

  template <class P, class Make>
  void add(const std::string& name, const std::string& doc, ParamDecl<P> decl, Make make) {
    add<P>(name, StrategyTraits{}, doc, std::move(decl), std::move(make));
  }
  template <class P, class Make>
  void add(const std::string& name, StrategyTraits t, const std::string& doc, ParamDecl<P> decl, Make make) {
    registry.add<P>(name, doc, std::move(decl),
                    std::function<Made(const P&, std::uint64_t)>(std::move(make)));
    traits.emplace(name, t);
  }
};

StrategyCatalog make_catalog() {
  StrategyCatalog r;
  r.add<EnergyAwareParams>(
      "energy_aware", StrategyTraits{.linear_scored = true},
      "energy-aware exploration, Rappaport 2016 Algorithm 1 (cost eq. 8, return threshold eq. 7)",
      energy_aware_params(), [](const EnergyAwareParams& p, std::uint64_t) -> Made {
        return std::make_unique<EnergyAware>("energy_aware", p);
      });
  r.add<ClosestFrontierParams>(
      "closest_frontier", StrategyTraits{.linear_scored = true},
      "nearest frontier by path length (Yamauchi 1997): energy_aware with weights (1, 0, 0, 0)",
      closest_frontier_params(), [](const ClosestFrontierParams& p, std::uint64_t) -> Made {
        EnergyAwareParams ea;
        ea.w1 = 1.0;
        ea.w2 = ea.w3 = ea.w4 = 0.0;
        ea.distance = p.distance;
        ea.goal = p.goal;
        return std::make_unique<EnergyAware>("closest_frontier", ea);
      });
  r.add<OrientationParams>(
      "orientation",
      "frontier cells of the sensing region walked clockwise from the robot's left (Mei 2006 IV-B)",
      orientation_params(),
      [](const OrientationParams& p, std::uint64_t) -> Made { return std::make_unique<Orientation>(p); });
  r.add<WidestFrontierParams>(
      "widest_frontier",
      "middle cell of the largest frontier group in the sensing region (Mei 2006's baseline)",
      widest_frontier_params(), [](const WidestFrontierParams& p, std::uint64_t) -> Made {
        return std::make_unique<WidestFrontier>(p);
      });
  r.add<GblParams>(
      "gbl", StrategyTraits{.seeded = true},
      "Gonzalez-Banos and Latombe: sampled candidates maximising I(p) exp(-lambda L(p)) (Holz 2010 eq. 3)",
      gbl_params(),
      [](const GblParams& p, std::uint64_t seed) -> Made { return std::make_unique<Gbl>(p, seed); });
  r.add<McdmParams>(
      "mcdm", "Basilico and Amigoni: criteria L, I, O aggregated by a Choquet integral (Holz 2010 Table I)",
      mcdm_params(), [](const McdmParams& p, std::uint64_t) -> Made { return std::make_unique<Mcdm>(p); });
  r.add<TargetSeekingParams>(
      "target_seeking", StrategyTraits{.linear_scored = true},
      "Arvanitakis et al.: reach a target in unknown space, frontier cost eq. 12", target_seeking_params(),
      [](const TargetSeekingParams& p, std::uint64_t) -> Made { return std::make_unique<TargetSeeking>(p); });
  r.add<NoParams>(
      "random_frontier", StrategyTraits{.seeded = true},
      "a reachable frontier cluster drawn uniformly (seeded); a baseline", ParamDecl<NoParams>{},
      [](const NoParams&, std::uint64_t seed) -> Made { return std::make_unique<RandomFrontier>(seed); });
  return r;
}

const StrategyCatalog& catalog() {
  static const StrategyCatalog kCatalog = make_catalog();
  return kCatalog;
}

}  // namespace

const StrategyRegistry& strategy_registry() { return catalog().registry; }

StrategyTraits strategy_traits(std::string_view name) {
  const auto it = catalog().traits.find(name);
  return it == catalog().traits.end() ? StrategyTraits{} : it->second;
}

StrategyConfig configure_strategy(const std::string& name, const nlohmann::json& params,
                                  const std::string& where, const std::string& params_where) {
  const std::string at = params_where.empty() ? where + "/params" : params_where;
  if (params.is_object() && params.contains("heuristics")) {
    throw ConfigError(
        param_path(at, "heuristics"),
        "heuristics are no longer a strategy parameter; give them beside \"params\" in the "
        "strategy entry: \"heuristics\": [\"rr\", \"seg\"] (or a list of such lists to sweep them)");
  }
  return strategy_registry().configure(name, params, where, at);
}

std::unique_ptr<Strategy> make_strategy(const std::string& name, const nlohmann::json& params,
                                        std::uint64_t seed, const std::string& where) {
  return configure_strategy(name, params, where).make(seed);
}

std::vector<std::string> strategy_names() { return strategy_registry().names(); }

}  // namespace strategies
}  // namespace fsweep
