#pragma once
/// @file jps_planner.hpp
/// `jps`: jump point search (Harabor & Grastien, "Online Graph Pruning for Pathfinding on Grid
/// Maps", AAAI 2011), an optimal 8-connected planner that returns the same shortest lengths as
/// `astar` while settling only jump points. It plans on the same cells and move rule as the grid
/// planners (src/search/octile_grid.hpp: known-free cells, octile costs) under either corner rule
/// of PlanRequest::allow_corner_cutting:
/// - without corner cutting (the default, MovingAI's rule; Harabor & Grastien, "The JPS+
///   Pathfinding System", SoCS 2012, section 3): diagonal moves have no forced neighbours; a
///   straight move from p to x has a forced neighbour x + q (q perpendicular) when x + q is free
///   and p + q is not, and x then also branches to x + q and the diagonal x + d + q;
/// - with corner cutting (a diagonal step needs only its target free, the 2011 paper's rules):
///   a straight move forces the diagonal x + d + q when x + q is blocked and x + d + q free; a
///   diagonal move (dx, dy) forces (-dx, dy) and (dx, -dy) past a blocked x - (dx, 0) or x - (0, dy).
/// A straight jump continues until it reaches the goal, a cell with a forced neighbour or a
/// blocked cell, scanning its row or column a word of 64 cells at a time (KnownMap's free bits;
/// Harabor & Grastien, "Improving Jump Point Search", ICAPS 2014), finding the same jump points as
/// a scan cell by cell. A diagonal jump steps one cell at a time until a step is not allowed and
/// at every cell runs the straight jumps along its two components; the jump points they find are
/// successors of the state jumped from, reached through that cell (the ICAPS 2014 paper's online
/// pruning: the 2011 search stops at the first such cell and opens it as a jump point of its
/// own, to be settled later only to make the same jumps). The diagonal cells are therefore never
/// opened, except the goal and, with corner cutting, a cell with a forced neighbour, which end the
/// jump. So `jps` settles fewer states than the 2011 search; its edges cover all of the 2011
/// search's, each at the octile length of its diagonal run and straight run, so its lengths are
/// the same. The A* runs on jump points (BestFirstSearch, octile heuristic); the direction of
/// arrival at a jump point is that of the last step from its parent: along the longer axis of the
/// two cells' offset, or diagonal if the two axes are equal.

#include <limits>
#include <memory>
#include <string>

#include "planners/planner.hpp"
#include "search/grid_search.hpp"

namespace fsweep {
inline namespace planners {

/// Parameters of `jps`: only the query budget (declare_budget() in budget_params.hpp); any other
/// key is a ConfigError.
struct JpsPlannerParams {
  /// Wall time of one query's search (seconds, > 0); +infinity (the default, JSON null): none.
  double time_limit_s = std::numeric_limits<double>::infinity();
  /// Jump points one query may settle (>= 0); 0 (the default): none.
  long max_expansions = 0;
};

/// Jump point search planner (see the file comment). Keeps its search arrays between queries
/// (not thread-safe).
///
/// Statuses (besides Planner::plan()'s endpoint checks): NoPath if the goal is not reachable
/// through known-free cells; Timeout if the time limit or the expansion budget ends the search
/// first; Success otherwise, with every cell of the path (the segments between jump points filled
/// in, each diagonal run before its straight run; start == goal gives the one-cell path). The length equals
/// `astar`'s (the same shortest octile length, so the same numbers of straight and diagonal steps), the path
/// itself may differ. `expansions` counts settled jump points, not the cells the jumps scan. Ties break as in
/// BestFirstSearch (smaller f, larger g, smaller cell index).
class JpsPlanner final : public Planner {
 public:
  /// Deterministic and length-optimal (fixed tie-breaking, a consistent heuristic).
  static constexpr PlannerCapabilities kCapabilities{Determinism::Always, true, false};

  explicit JpsPlanner(JpsPlannerParams params = {})
      : Planner(SearchBudget{params.time_limit_s, params.max_expansions}), params_(params) {}

  [[nodiscard]] std::string name() const override { return "jps"; }
  [[nodiscard]] std::unique_ptr<Planner> clone() const override;

  [[nodiscard]] const JpsPlannerParams& params() const { return params_; }

 protected:
  [[nodiscard]] SearchResult search(const KnownMap& known, const PlanRequest& request,
                                    const StopCondition& stop) override;

 private:
  JpsPlannerParams params_;
  OctileSearch search_;
};

}  // namespace planners
}  // namespace fsweep
