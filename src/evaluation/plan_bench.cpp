#include "evaluation/plan_bench.hpp"

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

#include "core/random.hpp"
#include "planners/registry.hpp"

namespace fsweep {
inline namespace evaluation {

std::vector<BenchQuery> bench_queries_from_scenario(const std::vector<ScenarioQuery>& scenario) {
  std::vector<BenchQuery> queries;
  for (const ScenarioQuery& q : scenario) {
    if (q.optimal_length > 0.0) queries.push_back(BenchQuery{q.start, q.goal, q.optimal_length});
  }
  return queries;
}

std::vector<BenchQuery> bench_queries_from_pairs(const KnownMap& known, const PairDrawOptions& options) {
  const std::vector<ComparePair> pairs = draw_compare_pairs(known, options);
  const std::unique_ptr<Planner> astar = make_planner("astar", nullptr);
  std::vector<BenchQuery> queries;
  queries.reserve(pairs.size());
  for (const ComparePair& p : pairs) {
    PlanRequest request;
    request.start = p.source;
    request.goal = p.target;
    request.allow_corner_cutting = options.allow_corner_cutting;
    const PlanResult r = astar->plan(known, request);
    if (r.status != PlanStatus::Success) throw std::logic_error("plan_bench: a drawn pair is not reachable");
    queries.push_back(BenchQuery{p.source, p.target, r.length_m / known.resolution_m()});
  }
  return queries;
}

std::vector<std::vector<BenchPlan>> run_plan_bench(const KnownMap& known,
                                                   const std::vector<BenchQuery>& queries,
                                                   const std::vector<std::unique_ptr<Planner>>& planners,
                                                   const BenchSettings& settings) {
  std::vector<std::vector<BenchPlan>> plans(planners.size(), std::vector<BenchPlan>(queries.size()));
  for (std::size_t i = 0; i < planners.size(); ++i) {
    for (std::size_t q = 0; q < queries.size(); ++q) {
      PlanRequest request;
      request.start = queries[q].start;
      request.goal = queries[q].goal;
      request.energy = settings.energy;
      request.allow_corner_cutting = settings.allow_corner_cutting;
      request.seed = derive_seed(settings.seed, "plan_bench") + q;
      request.progress_interval_s = settings.progress_interval_s;
      PlanResult r = planners[i]->plan(known, request);
      BenchPlan& p = plans[i][q];
      p.status = r.status;
      p.time_s = r.time_s;
      p.progress = std::move(r.progress);
      if (r.status == PlanStatus::Success) {
        p.length_cells = r.length_m / known.resolution_m();
        p.length_ratio = p.length_cells / queries[q].optimal_cells;
        p.energy = r.energy;
        p.turns = r.turns;
      }
    }
  }
  return plans;
}

BenchSummary summarize_plan_bench(const std::vector<BenchPlan>& plans) {
  BenchSummary s;
  s.queries = static_cast<int>(plans.size());
  std::vector<double> ratio;
  std::vector<double> energy;
  std::vector<double> turns;
  std::vector<double> time_ms;
  for (const BenchPlan& p : plans) {
    time_ms.push_back(p.time_s * 1000.0);
    if (p.status == PlanStatus::Timeout) ++s.timeouts;
    if (p.status != PlanStatus::Success) continue;
    ++s.solved;
    ratio.push_back(p.length_ratio);
    energy.push_back(p.energy);
    turns.push_back(static_cast<double>(p.turns));
  }
  s.success_rate = s.queries > 0 ? static_cast<double>(s.solved) / s.queries : 0.0;
  s.length_ratio = summarize_sample(std::move(ratio));
  s.energy = summarize_sample(std::move(energy));
  s.turns = summarize_sample(std::move(turns));
  s.time_ms = summarize_sample(std::move(time_ms));
  return s;
}

}  // namespace evaluation
}  // namespace fsweep
