#include "planners/ompl_space.hpp"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/ProjectionEvaluator.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>

namespace fsweep {
inline namespace planners {

namespace ob = ompl::base;

PlanePoint point_of(const ob::State* state) {
  const double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
  return PlanePoint{v[0], v[1]};
}

namespace {

/// A state is valid if the cell under it is known free.
class KnownFreeChecker final : public ob::StateValidityChecker {
 public:
  KnownFreeChecker(const ob::SpaceInformationPtr& si, const KnownMap& known)
      : ob::StateValidityChecker(si), known_(known) {}

  bool isValid(const ob::State* state) const override {
    checks_.fetch_add(1, std::memory_order_relaxed);
    const PlanePoint p = point_of(state);
    // Bounds first: cell_of() of a far-away point would overflow int.
    if (!(p.x >= 0.0 && p.y >= 0.0 && p.x < known_.width() && p.y < known_.height())) return false;
    return known_.is_free(cell_of(p));
  }

  /// Number of isValid() calls so far.
  [[nodiscard]] long checks() const { return checks_.load(std::memory_order_relaxed); }

 private:
  const KnownMap& known_;
  mutable std::atomic<long> checks_{0};
};

/// Exact motion check: check_segment() over the cells the segment crosses.
class GridMotionValidator final : public ob::MotionValidator {
 public:
  GridMotionValidator(ob::SpaceInformation* si, const KnownMap& known, bool allow_corner_cutting)
      : ob::MotionValidator(si), known_(known), allow_corner_cutting_(allow_corner_cutting) {}

  bool checkMotion(const ob::State* s1, const ob::State* s2) const override {
    const bool ok = check_segment(known_, point_of(s1), point_of(s2), allow_corner_cutting_).free;
    ++(ok ? valid_ : invalid_);
    return ok;
  }

  bool checkMotion(const ob::State* s1, const ob::State* s2,
                   std::pair<ob::State*, double>& last_valid) const override {
    const PlanePoint a = point_of(s1);
    const PlanePoint b = point_of(s2);
    const SegmentCheck check = check_segment(known_, a, b, allow_corner_cutting_);
    if (check.free) {
      ++valid_;
      return true;
    }
    ++invalid_;
    // The last valid state: just before the segment leaves its last allowed cell (1e-6 cell
    // back), or s1 itself if that point is not in a free cell.
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    double t = length > 0.0 ? std::max(0.0, check.blocked_t - 1e-6 / length) : 0.0;
    const PlanePoint p{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
    if (!known_.is_free(cell_of(p))) t = 0.0;
    last_valid.second = t;
    if (last_valid.first != nullptr) si_->getStateSpace()->interpolate(s1, s2, t, last_valid.first);
    return false;
  }

 private:
  const KnownMap& known_;
  bool allow_corner_cutting_;
};

/// The identity projection of R2 onto the plane (used by KPIECE1's discretisation), with
/// square cells of `cell_size` map cells. (Debian's OMPL 1.5 RealVectorIdentityProjection-
/// Evaluator fails an Eigen assertion on project().)
class PlaneProjection final : public ob::ProjectionEvaluator {
 public:
  PlaneProjection(const ob::StateSpace* space, double cell_size)
      : ob::ProjectionEvaluator(space), cell_size_(cell_size) {}

  unsigned int getDimension() const override { return 2; }
  void project(const ob::State* state, Eigen::Ref<Eigen::VectorXd> projection) const override {
    const PlanePoint p = point_of(state);
    projection(0) = p.x;
    projection(1) = p.y;
  }
  void defaultCellSizes() override { cellSizes_.assign(2, cell_size_); }

 private:
  double cell_size_;
};

/// R2 with PlaneProjection as its default projection: cells of 1/20 of the larger map side
/// (OMPL's own default for real vector spaces), at least one map cell.
class PlaneSpace final : public ob::RealVectorStateSpace {
 public:
  explicit PlaneSpace(double cell_size) : ob::RealVectorStateSpace(2), cell_size_(cell_size) {}
  void registerProjections() override {
    registerDefaultProjection(std::make_shared<PlaneProjection>(this, cell_size_));
  }

 private:
  double cell_size_;
};

}  // namespace

ob::SpaceInformationPtr make_grid_space_information(const KnownMap& known, bool allow_corner_cutting) {
  auto space = std::make_shared<PlaneSpace>(std::max(1.0, std::max(known.width(), known.height()) / 20.0));
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0, 0.0);
  bounds.setHigh(0, static_cast<double>(known.width()));
  bounds.setLow(1, 0.0);
  bounds.setHigh(1, static_cast<double>(known.height()));
  space->setBounds(bounds);
  auto si = std::make_shared<ob::SpaceInformation>(space);
  si->setStateValidityChecker(std::make_shared<KnownFreeChecker>(si, known));
  si->setMotionValidator(std::make_shared<GridMotionValidator>(si.get(), known, allow_corner_cutting));
  si->setup();
  return si;
}

long grid_validity_checks(const ob::SpaceInformation& si) {
  const auto& checker = static_cast<const KnownFreeChecker&>(*si.getStateValidityChecker());
  return checker.checks() + static_cast<long>(si.getMotionValidator()->getCheckedMotionCount());
}

}  // namespace planners
}  // namespace fsweep
