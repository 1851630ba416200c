#include "sim/metrics_recorder.hpp"

#include <utility>

namespace fsweep {
inline namespace sim {

void MetricsRecorder::sample_progress(double step_m, double explored_area_m2, double coverage) {
  while (metrics_.distance_m + 1e-9 >= next_progress_m_) {
    progress_.push_back(ProgressSample{next_progress_m_, explored_area_m2, coverage, metrics_.energy});
    next_progress_m_ += step_m;
  }
}

void MetricsRecorder::end(EndReason reason, std::string detail) {
  ended_ = true;
  end_ = reason;
  end_detail_ = std::move(detail);
}

void MetricsRecorder::reach_target(std::string detail) {
  end(EndReason::TargetReached, std::move(detail));
  metrics_.target_path_m = metrics_.distance_m;
  if (metrics_.target_shortest_m > 0.0) {
    metrics_.target_path_ratio = metrics_.target_path_m / metrics_.target_shortest_m;
  }
}

RunResult MetricsRecorder::result() const& { return MetricsRecorder(*this).result(); }

RunResult MetricsRecorder::result() && {
  RunResult r;
  r.end = end_;
  r.end_detail = std::move(end_detail_);
  r.metrics = metrics_;
  r.progress = std::move(progress_);
  r.trajectory = std::move(trajectory_);
  r.recharge_steps = std::move(recharge_steps_);
  return r;
}

}  // namespace sim
}  // namespace fsweep
