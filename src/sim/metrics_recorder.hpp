#pragma once
/// @file metrics_recorder.hpp
/// The record part of a Simulation: the metrics counted so far, the progress curve, the
/// trajectory, the recharges and, once the run is over, why it ended. A plain value.

#include <string>
#include <vector>

#include "sim/run_result.hpp"
#include "world/grid.hpp"

namespace fsweep {
inline namespace sim {

class MetricsRecorder {
 public:
  MetricsRecorder() = default;
  /// A record whose trajectory starts at `start`.
  explicit MetricsRecorder(Cell start) : trajectory_{start} {}

  /// The metrics counted so far (the engine adds to them as the run goes).
  [[nodiscard]] RunMetrics& metrics() { return metrics_; }
  [[nodiscard]] const RunMetrics& metrics() const { return metrics_; }

  /// Appends the robot's new cell to the trajectory.
  void record_position(Cell c) { trajectory_.push_back(c); }
  /// Counts one step of travel in heading `heading` (odd: diagonal) on cells of `resolution_m`:
  /// distance_m is computed from the counts of straight and diagonal steps, exact as path
  /// lengths are (world/motion.hpp), not summed step by step.
  void record_step(int heading, double resolution_m) {
    ++((heading & 1) != 0 ? diagonal_steps_ : straight_steps_);
    metrics_.distance_m =
        (static_cast<double>(straight_steps_) + static_cast<double>(diagonal_steps_) * kSqrt2) * resolution_m;
  }
  /// Counts a recharge at the current (last) trajectory cell.
  void record_recharge() {
    ++metrics_.recharges;
    recharge_steps_.push_back(static_cast<int>(trajectory_.size()) - 1);
  }
  /// Adds a progress sample at every multiple of `step_m` (metres) of travel reached since the
  /// last one, with the current explored area (m^2) and coverage.
  void sample_progress(double step_m, double explored_area_m2, double coverage);

  /// Ends the run with `reason` and `detail` (free text for RunResult::end_detail).
  void end(EndReason reason, std::string detail = {});
  /// Ends the run TargetReached with `detail` and sets target_path_m and target_path_ratio.
  void reach_target(std::string detail);
  [[nodiscard]] bool ended() const { return ended_; }

  /// The record as a result: end reason and detail, metrics, progress, trajectory, recharges.
  /// The caller adds what depends on the map (areas, coverage, the final map).
  [[nodiscard]] RunResult result() const&;
  /// The same, moving the trajectory and the progress curve out instead of copying them.
  [[nodiscard]] RunResult result() &&;

 private:
  RunMetrics metrics_;
  long straight_steps_ = 0;
  long diagonal_steps_ = 0;
  std::vector<ProgressSample> progress_;
  /// The travel distance (metres) of the next progress sample.
  double next_progress_m_ = 0.0;
  std::vector<Cell> trajectory_;
  std::vector<int> recharge_steps_;
  bool ended_ = false;
  EndReason end_ = EndReason::Error;
  std::string end_detail_;
};

}  // namespace sim
}  // namespace fsweep
