#include "sim/grid_distance_oracle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsweep {
inline namespace sim {

GridDistanceOracle::GridDistanceOracle(const KnownMap& known, Cell robot, Cell dock,
                                       bool allow_corner_cutting, DockField* dock_field,
                                       DistanceScratch& scratch)
    : known_(known),
      robot_(robot),
      dock_(dock),
      corner_cutting_(allow_corner_cutting),
      dock_field_(dock_field),
      scratch_(scratch) {
  scratch_.bound_m_ = -1.0;
  scratch_.probed_.clear();
  scratch_.probed_from_ = robot;
  scratch_.probed_map_ = known.instance_id();
  scratch_.probed_revision_ = known.revision();
  scratch_.probed_corner_cutting_ = allow_corner_cutting;
}

std::optional<SearchResult> DistanceScratch::probed_path(const KnownMap& known, Cell start, Cell goal,
                                                         bool allow_corner_cutting) const {
  if (start != probed_from_ || known.instance_id() != probed_map_ || known.revision() != probed_revision_ ||
      allow_corner_cutting != probed_corner_cutting_ || !known.in_bounds(goal)) {
    return std::nullopt;
  }
  const int g = known.index(goal);
  const auto p = std::find_if(probed_.begin(), probed_.end(), [g](const Probed& q) { return q.goal == g; });
  if (p == probed_.end()) return std::nullopt;
  SearchResult found;
  found.status = PlanStatus::Success;
  found.expansions = p->expansions;
  found.path.reserve(p->path.size());
  for (const int i : p->path) found.path.push_back(known.cell(i));
  return found;
}

std::vector<double> GridDistanceOracle::lookup(Cell source, std::span<const int> cells, double bound_m) {
  // The search stops once every asked cell is settled, so the field answers again only the
  // same cells from the same source with a bound at least as large.
  DistanceScratch& s = scratch_;
  if (s.bound_m_ < bound_m || s.source_ != source ||
      !std::equal(cells.begin(), cells.end(), s.cells_.begin(), s.cells_.end())) {
    DistanceQuery q;
    q.max_distance_m = bound_m;
    q.allow_corner_cutting = corner_cutting_;
    q.stop_when_all_settled = cells;
    s.field_.compute(known_, source, q);
    s.source_ = source;
    s.bound_m_ = bound_m;
    s.cells_.assign(cells.begin(), cells.end());
    expansions_ += s.field_.expansions();
  }
  std::vector<double> out;
  out.reserve(cells.size());
  for (const int i : cells) {
    const double d = s.field_.distance_m(i);
    out.push_back(d <= bound_m ? d : std::numeric_limits<double>::infinity());
  }
  return out;
}

std::vector<double> GridDistanceOracle::from_robot(std::span<const int> cells, double bound_m) {
  return lookup(robot_, cells, bound_m);
}

std::vector<double> GridDistanceOracle::from_dock(std::span<const int> cells, double bound_m) {
  if (dock_field_ == nullptr || !dock_field_->ready()) return lookup(dock_, cells, bound_m);
  expansions_ += dock_field_->bring_up_to_date(known_);
  std::vector<double> out;
  out.reserve(cells.size());
  for (const int i : cells) {
    const double d = dock_field_->distance_m(i);
    out.push_back(d <= bound_m ? d : std::numeric_limits<double>::infinity());
  }
  return out;
}

int GridDistanceOracle::nearest_from_robot(std::span<const int> cells) {
  if (cells.empty()) return -1;
  DistanceScratch& s = scratch_;
  const bool held = s.bound_m_ == std::numeric_limits<double>::infinity() && s.source_ == robot_ &&
                    std::equal(cells.begin(), cells.end(), s.cells_.begin(), s.cells_.end());
  if (!held) {
    DistanceQuery q;
    q.allow_corner_cutting = corner_cutting_;
    q.stop_at_first_of = cells;
    s.field_.compute(known_, robot_, q);
    s.bound_m_ = -1.0;  // exact for the nearest cells only
    expansions_ += s.field_.expansions();
  }
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const double d = s.field_.distance_m(cells[k]);
    if (d < best_d) {  // strict: ties keep the lowest position
      best_d = d;
      best = static_cast<int>(k);
    }
  }
  return best;
}

void GridDistanceOracle::watch_from_robot(std::span<const int> cells, double bound_m,
                                          SettleWatcher& watcher) {
  // A watched search may end early, so it must not pass for a settle-all one.
  DistanceQuery q;
  q.max_distance_m = bound_m;
  q.allow_corner_cutting = corner_cutting_;
  q.stop_when_all_settled = cells;
  q.watcher = &watcher;
  scratch_.field_.compute(known_, robot_, q);
  scratch_.bound_m_ = -1.0;
  expansions_ += scratch_.field_.expansions();
}

std::optional<double> GridDistanceOracle::probe_from_robot(int cell, double bound_m, long max_expansions) {
  DistanceQuery q;
  q.max_distance_m = bound_m;
  q.allow_corner_cutting = corner_cutting_;
  q.stop = StopCondition(SearchBudget{std::numeric_limits<double>::infinity(), max_expansions},
                         StopCondition::Clock::time_point{});
  PathProbe& probe = scratch_.probe_;
  const std::optional<double> d = probe.compute_to(known_, robot_, known_.cell(cell), q);
  // The probes no longer run in field_, but a later lookup() still searches again, as when they
  // did: the runs' planner_expansions stay what they were.
  scratch_.bound_m_ = -1.0;
  expansions_ += probe.expansions();
  if (probe.reached_goal())
    scratch_.probed_.push_back(DistanceScratch::Probed{cell, probe.path(), probe.expansions()});
  if (!d) return std::nullopt;
  return *d <= bound_m ? *d : std::numeric_limits<double>::infinity();
}

std::vector<double> GridDistanceOracle::lower_bounds_from_robot(std::span<const int> cells) const {
  // The octile length is exact: the fields' costs count straight and diagonal steps
  // (search/grid_search.hpp, OctileCost), and no path has a smaller value. The triangle bound
  // subtracts two rounded lengths: allow a relative 1e-9.
  constexpr double kSlack = 1e-9;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double res = known_.resolution_m();
  const bool triangle = dock_field_ != nullptr && dock_field_->current() &&
                        std::isfinite(dock_field_->distance_m(known_.index(robot_)));
  const double to_robot = triangle ? dock_field_->distance_m(known_.index(robot_)) : 0.0;
  std::vector<double> out;
  out.reserve(cells.size());
  for (const int cell : cells) {
    double bound = octile_distance(robot_, known_.cell(cell)) * res;
    if (triangle) {
      const double to_cell = dock_field_->distance_m(cell);
      if (!std::isfinite(to_cell)) {
        bound = kInf;
      } else {
        bound = std::max(bound, to_cell - to_robot - kSlack * (to_cell + to_robot));
      }
    }
    out.push_back(bound);
  }
  return out;
}

}  // namespace sim
}  // namespace fsweep
