#include "sim/dock_field.hpp"

#include <algorithm>
#include <atomic>

namespace fsweep {
inline namespace sim {

std::size_t DockField::rebuild_after(int cells) {
  return std::max<std::size_t>(static_cast<std::size_t>(cells) / 16, 1024);
}

void DockField::take_in(const KnownMap& known, std::span<const int> revealed, Cell dock,
                        bool allow_corner_cutting) {
  if (!ready_) {
    ready_ = known.is_free(dock);
    dock_ = dock;
    allow_corner_cutting_ = allow_corner_cutting;
    return;
  }
  if (field_ == nullptr || rebuild_) return;  // the next build reads the map as it is then
  if (pending_.size() + revealed.size() > rebuild_after(known.size())) {
    rebuild_ = true;
    pending_.clear();
    return;
  }
  pending_.insert(pending_.end(), revealed.begin(), revealed.end());
}

long DockField::bring_up_to_date(const KnownMap& known) {
  if (current()) return 0;
  // Copy on write: another DockField (a fork's) still reads the shared field. A count of 1
  // cannot grow meanwhile: only this object could hand out a new reference. The fence orders
  // the in-place update after the last reads of forks (on other threads) that released it.
  const bool build = field_ == nullptr || rebuild_;
  if (field_ != nullptr && field_.use_count() > 1) {
    field_ = build ? std::make_shared<IncrementalDistanceField>()
                   : std::make_shared<IncrementalDistanceField>(*field_);
  } else if (field_ != nullptr) {
    std::atomic_thread_fence(std::memory_order_acquire);
  } else {
    field_ = std::make_shared<IncrementalDistanceField>();
  }
  if (build) {
    field_->reset(known, dock_, allow_corner_cutting_);
  } else {
    field_->update(known, pending_);
  }
  pending_.clear();
  rebuild_ = false;
  return field_->expansions();
}

}  // namespace sim
}  // namespace fsweep
