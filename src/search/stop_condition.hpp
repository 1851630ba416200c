#pragma once
/// @file stop_condition.hpp
/// When a search must give up, as a small value (OMPL's PlannerTerminationCondition without the
/// callback): a wall-time limit and an expansion budget. Planner::plan() makes one per query from
/// the planner's parameters (src/planners/planner.hpp); BestFirstSearch, DistanceField and the
/// OMPL adapter honour it.

#include <chrono>
#include <limits>

namespace fsweep {
inline namespace search {

/// What one query may spend, as a planner's parameters state it.
struct SearchBudget {
  /// Wall time of the search (seconds, > 0); +infinity: no limit.
  double time_limit_s = std::numeric_limits<double>::infinity();
  /// Expansions allowed (settled states; OMPL: termination checks, about one per iteration);
  /// 0: no limit (as OMPL's `max_iterations`).
  long max_expansions = 0;
};

/// A SearchBudget running from a start time. Copyable and cheap; reading it never allocates.
class StopCondition {
 public:
  using Clock = std::chrono::steady_clock;

  /// Reads of the clock by should_stop(): one every this many expansions (a settled state costs
  /// tens to hundreds of nanoseconds, a clock read about twenty).
  static constexpr long kClockInterval = 256;
  /// Longest time limit kept (seconds, about 31 years): longer ones, +infinity included, are none.
  static constexpr double kMaxTimeLimitS = 1e9;

  /// Never stops.
  StopCondition() = default;
  /// Stops `budget.time_limit_s` seconds after `started` (limits beyond kMaxTimeLimitS count as
  /// none), or once `budget.max_expansions` expansions were made.
  StopCondition(const SearchBudget& budget, Clock::time_point started)
      : max_expansions_(budget.max_expansions > 0 ? budget.max_expansions : kNoBudget),
        timed_(budget.time_limit_s <= kMaxTimeLimitS) {
    if (timed_) {
      time_limit_ =
          std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(budget.time_limit_s));
      deadline_ = started + time_limit_;
    }
  }

  /// True once `expansions` (made so far) reach the budget: exact, no clock read.
  [[nodiscard]] bool budget_spent(long expansions) const { return expansions >= max_expansions_; }
  /// True once the time limit has passed (reads the clock if there is one).
  [[nodiscard]] bool time_up() const { return timed_ && Clock::now() >= deadline_; }
  /// The check of a search loop before its next expansion: budget_spent(), and time_up() every
  /// kClockInterval expansions (starting with the first, so a time limit that has already passed
  /// stops the search before it expands anything).
  [[nodiscard]] bool should_stop(long expansions) const {
    return budget_spent(expansions) ||
           (timed_ && expansions % kClockInterval == 0 && Clock::now() >= deadline_);
  }
  /// The same time limit with the budget lowered by `used` expansions: for a search in phases
  /// that share one budget.
  [[nodiscard]] StopCondition after_expansions(long used) const {
    StopCondition rest = *this;
    if (max_expansions_ != kNoBudget) rest.max_expansions_ = max_expansions_ - used;
    return rest;
  }
  /// The same budget with the clock restarted at `now`: for a search that first waits for a
  /// shared resource (the OMPL planners wait for a process-wide lock).
  [[nodiscard]] StopCondition restarted(Clock::time_point now) const {
    StopCondition fresh = *this;
    fresh.deadline_ = now + time_limit_;
    return fresh;
  }

 private:
  static constexpr long kNoBudget = std::numeric_limits<long>::max();
  long max_expansions_ = kNoBudget;
  bool timed_ = false;
  Clock::duration time_limit_{};
  Clock::time_point deadline_{};
};

}  // namespace search
}  // namespace fsweep
