#include "time/w_cycle.hpp"

#include <bit>
#include <stdexcept>

namespace mrsim {

WCycle::WCycle(int max_level) : max_level_(max_level) {
  if (max_level < 0 || max_level > 30) throw std::invalid_argument("WCycle: max_level out of range");
}

int WCycle::coarse_level(int t) const {
  if (t <= 0) return -1;  // the frame start: only the finest level's step opens there
  const int k = max_level_ - 1 - std::countr_zero(static_cast<unsigned>(t));
  return k >= 0 ? k : -1;
}

// The step of a level-k kick at t (t in the middle) ends at t + period(k)/2. The next level's
// step starting there has its kick at its start (finest level) or in its middle.
int WCycle::first_kick_after_refining(int k, int t) const {
  const int end = t + period(k) / 2;
  return k + 1 == max_level_ ? end : end + period(k + 1) / 2;
}

}  // namespace mrsim
