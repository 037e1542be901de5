#pragma once
// The W-cycle ("ruler sequence") schedule of method.md §5.4, as kick times of a multirate
// kick-drift scheme. A frame has 2^K ticks, K the finest allowed time level (h = frame_dt / 2^K).
// Every particle drifts (u += v dt) continuously, so neighbours are always read at the current
// time; a level-k particle is kicked (v += f dt_k / m) once per step dt_k = 2^(K-k) h:
//   - level K at every tick t (its kick opens the step [t, t + h]: the global-step scheme);
//   - a coarser level k at the middle of each of its steps, t = (j + 1/2) 2^(K-k) h, i.e. at the
//     ticks with ctz(t) = K - 1 - k (the ruler sequence).
// So level k is kicked 2^k times per frame at equal spacing, no tick kicks more than two levels
// (K and one coarser), the coarse kicks are spread over the frame instead of piling up at its
// end, each coarse kick samples the force at the middle of its step (the leap-frog flavour), and
// every level's steps end with the frame.
namespace mrsim {

class WCycle {
 public:
  explicit WCycle(int max_level);

  int max_level() const { return max_level_; }
  int ticks_per_frame() const { return 1 << max_level_; }
  /// Length of a level-k step in ticks.
  int period(int k) const { return 1 << (max_level_ - k); }
  /// The level kicked at tick t (0 <= t < ticks_per_frame) besides max_level, or -1.
  int coarse_level(int t) const;
  /// Is tick t a kick time of level k?
  bool kicks(int k, int t) const { return k == max_level_ || coarse_level(t) == k; }
  /// A particle kicked at tick t on level k < max_level goes to level k + 1 at once: its first
  /// kick there, the one whose step starts where the step of its last kick ends.
  int first_kick_after_refining(int k, int t) const;

 private:
  int max_level_;
};

}  // namespace mrsim
