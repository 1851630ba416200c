#include "sim/dock_field.hpp"

#include <atomic>

namespace fsweep {
inline namespace sim {

void DockField::take_in(const KnownMap& known, std::span<const int> revealed, Cell dock,
                        bool allow_corner_cutting) {
  if (field_) {
    pending_.insert(pending_.end(), revealed.begin(), revealed.end());
  } else if (known.is_free(dock)) {
    auto field = std::make_shared<IncrementalDistanceField>();
    field->reset(known, dock, allow_corner_cutting);
    field_ = std::move(field);
  }
}

long DockField::bring_up_to_date(const KnownMap& known) {
  if (pending_.empty()) return 0;
  // Copy on write: another DockField (a fork's) still reads the shared field. A count of 1
  // cannot grow meanwhile: only this object could hand out a new reference. The fence orders
  // the in-place update after the last reads of forks (on other threads) that released it.
  if (field_.use_count() > 1) {
    field_ = std::make_shared<IncrementalDistanceField>(*field_);
  } else {
    std::atomic_thread_fence(std::memory_order_acquire);
  }
  field_->update(known, pending_);
  pending_.clear();
  return field_->expansions();
}

}  // namespace sim
}  // namespace fsweep
