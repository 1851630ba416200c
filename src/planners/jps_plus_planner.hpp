#pragma once
/// @file jps_plus_planner.hpp
/// `jps+`: jump point search over precomputed jump distances (Harabor & Grastien, "The JPS+
/// Pathfinding System", SoCS 2012; S. Rabin, "JPS+: Over 100x Faster than A*", Game AI Pro 2,
/// 2015). For every cell and each of the 8 headings a table holds where a jump from that cell
/// stops: d > 0 steps to the next jump point, or -d >= 0 free steps before the next step is not
/// allowed (a blocked cell, the grid's edge, or a diagonal past a blocked corner). A straight jump
/// point is a cell with a forced neighbour on arrival in that direction; a diagonal jump stops at
/// a cell with a forced neighbour (corner cutting only) or from which a straight jump along either
/// component has a jump point: the rules of `jps` (jps_planner.hpp), under either corner rule of
/// PlanRequest::allow_corner_cutting, one table each. A query is then `jps`'s A* over jump points
/// with every jump read in O(1), diagonals followed as `jps` follows them (the straight jumps'
/// jump points from each diagonal jump point are successors of the state jumped from; the
/// diagonal jump points themselves are not opened): only the goal needs checks of its own
/// (Rabin's "target jump points"): a straight jump reaches it when it lies ahead on the line
/// within |d| steps; a diagonal jump whose quadrant holds the goal stops, when min(|dx|, |dy|) to
/// the goal is within |d| steps, at the cell of that many diagonal steps, on the goal's row or
/// column, which is opened.
///
/// Static maps only pay off. The table is rebuilt (O(cells), every cell and heading) by the first
/// query after the map changed (KnownMap::instance_id() and revision()); on an unchanged map (a
/// `fsweep plan --scen` batch, plan-bench, plan-compare) every query reuses it. Inside an
/// exploration the map changes with every scan, so every query rebuilds it: there `jps` is the
/// better choice (docs/planners.md has the measurements).

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "planners/planner.hpp"
#include "search/grid_search.hpp"

namespace fsweep {
inline namespace planners {

/// Parameters of `jps+`: only the query budget (declare_budget() in budget_params.hpp); any other
/// key is a ConfigError.
struct JpsPlusPlannerParams {
  /// Wall time of one query (seconds, > 0), a table rebuild included; +infinity (the default,
  /// JSON null): none.
  double time_limit_s = std::numeric_limits<double>::infinity();
  /// Jump points one query may settle (>= 0); 0 (the default): none.
  long max_expansions = 0;
};

/// JPS+ planner (see the file comment). Keeps its tables and search arrays between queries (not
/// thread-safe); a clone starts without tables.
///
/// Statuses (besides Planner::plan()'s endpoint checks): NoPath if the goal is not reachable
/// through known-free cells; Timeout if the time limit or the expansion budget ends the search
/// first (a rebuild always finishes: a time limit shorter than it ends the query as Timeout before
/// the first expansion, and the table stays for the next query); Success otherwise, with every
/// cell of the path. The length equals `astar`'s; the path may differ from `jps`'s (the diagonal
/// stops at the goal's row or column are extra jump points). `expansions` counts settled jump
/// points. Ties break as in BestFirstSearch (smaller f, larger g, smaller cell index).
///
/// Memory: 16 bytes a cell for each corner rule queried (8 headings of int16 distances, a cell's
/// together: one read of a cache line per expansion), plus a byte a cell (the free cells with a
/// blocked border) for rebuilds. Distances longer than 32767 steps are cut by extra jump points,
/// which cost expansions, not optimality.
class JpsPlusPlanner final : public Planner {
 public:
  /// Deterministic and length-optimal (fixed tie-breaking, a consistent heuristic).
  static constexpr PlannerCapabilities kCapabilities{Determinism::Always, true, false};

  explicit JpsPlusPlanner(JpsPlusPlannerParams params = {})
      : Planner(SearchBudget{params.time_limit_s, params.max_expansions}), params_(params) {}

  [[nodiscard]] std::string name() const override { return "jps+"; }
  [[nodiscard]] std::unique_ptr<Planner> clone() const override;

  [[nodiscard]] const JpsPlusPlannerParams& params() const { return params_; }
  /// Tables built so far (by every query that found its map changed).
  [[nodiscard]] long table_builds() const { return table_builds_; }
  /// Wall time of those builds together (seconds; part of the queries' time_s).
  [[nodiscard]] double table_build_time_s() const { return table_build_time_s_; }

 protected:
  [[nodiscard]] SearchResult search(const KnownMap& known, const PlanRequest& request,
                                    const StopCondition& stop) override;

 private:
  /// The jump distances of one corner rule: heading h of cell i at [i * 8 + h] (headings as in
  /// grid.hpp), for the map state they were built from.
  struct JumpTable {
    std::vector<std::int16_t> distances;
    /// KnownMap::instance_id() when built; 0: never built.
    std::uint64_t instance_id = 0;
    /// KnownMap::revision() when built.
    std::uint64_t revision = 0;
  };

  /// The table of `known` under the corner rule, rebuilt first if the map changed since.
  const JumpTable& refresh(const KnownMap& known, bool allow_corner_cutting);

  JpsPlusPlannerParams params_;
  /// Indexed by allow_corner_cutting.
  std::array<JumpTable, 2> tables_;
  /// The free cells of the map being tabulated, with a one-cell blocked border.
  std::vector<std::uint8_t> padded_free_;
  long table_builds_ = 0;
  double table_build_time_s_ = 0.0;
  OctileSearch search_;
};

}  // namespace planners
}  // namespace fsweep
