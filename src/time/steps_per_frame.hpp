#pragma once
// How many equal steps a frame takes for a step of at most `allowed` (docs/integrators.md "The
// stable step"): the computed time.substeps and, during a run, time.adapt_substeps.

namespace mrsim {

/// Steps per frame mrsim allows: more would never finish a frame.
inline constexpr int kMaxSubsteps = 1 << 30;

/// The fewest steps n, a multiple of `parts`, with frame_dt / n <= allowed; at most the largest
/// multiple of `parts` within `cap`. 1 × parts when `allowed` exceeds the frame.
long long fewest_steps(double frame_dt, double allowed, int parts, long long cap);

}  // namespace mrsim
