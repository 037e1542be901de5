#include "physics/material_law.hpp"

#include <cmath>

namespace mrsim {
double MaterialLaw::p_wave_speed() const { return std::sqrt((lambda + 2 * mu) / density); }
}  // namespace mrsim
