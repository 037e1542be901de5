#pragma once
// What the penalty contact of the tools can add to the stable step of a point (docs/contact.md
// "Contact and the stable step"). A skin vertex s in contact is a spring k_s A_s (N/m) along
// the tool's normal n, tied to the active points that move it with the skin map's weights w:
// its energy ½ k_s A_s (n · Σ_a w_a u_a)² is at most ½ k_s A_s Σ_a |w_a| Σ_b |w_b| |u_a|²
// (Cauchy–Schwarz), the form of physics/stable_step_bound.hpp. Summed over the vertices point
// a moves, but never more than a tool presses at once: its contact area (tool_shape.hpp) at
// the largest pressure stiffness among them. Damping on the approach speed has the same form
// with the damping coefficient.
#include <functional>
#include <vector>

#include "contact/skin.hpp"
#include "contact/tool.hpp"
#include "hierarchy/active_row.hpp"
#include "physics/stable_step_bound.hpp"

namespace mrsim {

/// The penalty of every skin vertex, the largest over the tools.
struct SkinPenalty {
  std::vector<double> stiffness;  // Pa/m, per skin vertex
  std::vector<double> damping;    // Pa·s/m, per skin vertex
  std::vector<double> area;       // m², per skin vertex
  double area_cap = 0;            // m², the largest contact_area of the tools
};

/// Per tool and skin vertex, the pressure stiffness (Pa/m): the tool's own, or `auto` (0):
/// (λ + 2μ)/h_s, h_s the mean length of the skin edges at the vertex.
std::vector<double> penalty_stiffness(const Skin& skin, const Tool& tool, double p_wave_modulus);

SkinPenalty skin_penalty(const Skin& skin, const std::vector<Tool>& tools, double p_wave_modulus);

/// The skin vertices a tool may reach during a run of `duration` s: within twice its bounding
/// radius of its path, sampled 16 times per display frame (the skin moves away from a tool that
/// presses it). Sorted.
std::vector<int> reachable_skin(const Skin& skin, const std::vector<Tool>& tools, double duration,
                                double frame_dt);

/// The row of a skin vertex: the points that move it and their weights (level -1: the
/// support, skipped).
using SkinRow = std::function<void(int vertex, std::vector<ActiveTerm>& row)>;

/// Adds the contact bounds of these skin vertices (the ones a tool may touch) to
/// out[level][point].stiffness / .damping. O(vertices × row length), nothing per point.
void add_contact_bounds(const SkinPenalty& penalty, const std::vector<int>& vertices,
                        const SkinRow& row_of, std::vector<std::vector<PointInertia>>& out);

}  // namespace mrsim
