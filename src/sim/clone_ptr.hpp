#pragma once
/// @file clone_ptr.hpp
/// An owning pointer to a plugin (Strategy, Planner) that copies by clone(), so a Simulation
/// holding its plugins by ClonePtr copies with `= default`.

#include <memory>
#include <utility>

namespace fsweep {
inline namespace sim {

/// Owns one `T` (or nothing). Copying calls `T::clone()` (which must return a
/// std::unique_ptr<T> to an equal copy of the dynamic type); moving moves the pointer.
template <typename T>
class ClonePtr {
 public:
  ClonePtr() = default;
  explicit ClonePtr(std::unique_ptr<T> owned) : owned_(std::move(owned)) {}
  ClonePtr(const ClonePtr& other) : owned_(other.owned_ ? other.owned_->clone() : nullptr) {}
  ClonePtr& operator=(const ClonePtr& other) {
    if (this != &other) owned_ = other.owned_ ? other.owned_->clone() : nullptr;
    return *this;
  }
  ClonePtr(ClonePtr&&) noexcept = default;
  ClonePtr& operator=(ClonePtr&&) noexcept = default;
  ~ClonePtr() = default;

  [[nodiscard]] T& operator*() const { return *owned_; }
  [[nodiscard]] T* operator->() const { return owned_.get(); }
  [[nodiscard]] T* get() const { return owned_.get(); }

 private:
  std::unique_ptr<T> owned_;
};

}  // namespace sim
}  // namespace fsweep
