#pragma once
// The box of a tool's sampled path, for the broad phases (skin_contact.cpp once per frame,
// contact_bound.cpp once per run): every sample, and every segment between two samples, lies in
// it, so a skin vertex farther from the box than the reach is farther than the reach from all of
// them and is passed without measuring each (most of the skin).
#include <span>

#include "core/vec.hpp"

namespace mrsim {

class PathBox {
 public:
  explicit PathBox(std::span<const Vec3> path) : lo_(path.front()), hi_(path.front()) {
    for (const Vec3& p : path) {
      lo_ = lo_.cwiseMin(p);
      hi_ = hi_.cwiseMax(p);
    }
  }
  /// Is x farther than `reach` from the box (with a margin for rounding, so that no vertex
  /// within reach of a sample is ever passed)?
  bool beyond(const Vec3& x, double reach) const {
    return (lo_ - x).cwiseMax(x - hi_).cwiseMax(0.0).norm() > reach * (1 + 1e-9);
  }

 private:
  Vec3 lo_, hi_;
};

}  // namespace mrsim
