#include "contact/tool_surface.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/portable_math.hpp"

namespace mrsim {

namespace {

// Every tool shape is a surface of revolution about z: a meridian profile (rho, z) from the
// bottom of the axis to its top, swept around it. Points on the axis become one vertex (a
// pole), the others a ring of `segments` vertices; consecutive profile points bound a band.
struct ProfilePoint {
  double rho;
  double z;
};
using Profile = std::vector<ProfilePoint>;

// Quarter circle of radius r centred on the axis at height zc, from angle a0 to a1 measured
// from the +rho direction (a = -pi/2 is the bottom pole, +pi/2 the top pole).
void add_arc(Profile& profile, double r, double zc, double a0, double a1, int steps) {
  for (int i = 0; i <= steps; ++i) {
    const double a = a0 + (a1 - a0) * i / steps;
    // Exact zeros on the axis so poles are recognised (cos(pi/2) is not 0 in floating point).
    const double rho =
        std::abs(std::abs(a) - std::numbers::pi / 2) < 1e-15 ? 0.0 : r * portable::cos(a);
    profile.push_back({rho, zc + r * portable::sin(a)});
  }
}

Profile profile_of(const ToolShape& s, int segments) {
  constexpr double half_pi = std::numbers::pi / 2;
  const double r = s.radius, L = s.length;
  const int quarter = std::max(2, segments / 4);  // arc steps per quarter circle
  Profile profile;
  switch (s.kind) {
    case ToolShapeKind::Sphere:
      add_arc(profile, r, 0, -half_pi, half_pi, 2 * quarter);
      break;
    case ToolShapeKind::Capsule:  // the cylinder is the band between the two equators
      add_arc(profile, r, 0, -half_pi, 0, quarter);
      add_arc(profile, r, L, 0, half_pi, quarter);
      break;
    case ToolShapeKind::FlatCylinder:
      profile = {{0, 0}, {r, 0}, {r, L}, {0, L}};
      break;
  }
  // A zero-length capsule or punch repeats a profile point: drop it (no degenerate band).
  profile.erase(std::unique(profile.begin(), profile.end(),
                            [](const ProfilePoint& a, const ProfilePoint& b) {
                              return a.rho == b.rho && a.z == b.z;
                            }),
                profile.end());
  return profile;
}

// Adds the vertices of one profile point; returns the index of its first vertex.
int add_ring(TriangleSurface& surface, const ProfilePoint& p, int segments) {
  const int first = static_cast<int>(surface.points.size());
  if (p.rho == 0) {
    surface.points.emplace_back(0, 0, p.z);
    return first;
  }
  for (int i = 0; i < segments; ++i) {
    const double phi = 2 * std::numbers::pi * i / segments;
    surface.points.emplace_back(p.rho * portable::cos(phi), p.rho * portable::sin(phi), p.z);
  }
  return first;
}

// The band between a lower ring a and an upper ring b (either may be a pole). Going up the
// meridian and counter-clockwise around z, (a_i, a_i+1, b_i+1) faces outwards.
void add_band(TriangleSurface& surface, int a, bool a_pole, int b, bool b_pole, int segments) {
  if (a_pole && b_pole) return;
  for (int i = 0; i < segments; ++i) {
    const int j = (i + 1) % segments;
    const int ai = a_pole ? a : a + i, aj = a_pole ? a : a + j;
    const int bi = b_pole ? b : b + i, bj = b_pole ? b : b + j;
    if (!a_pole) surface.triangles.push_back({ai, aj, bj});
    if (!b_pole) surface.triangles.push_back({ai, bj, bi});
  }
}

}  // namespace

TriangleSurface tool_surface(const ToolShape& shape, int segments) {
  segments = std::max(segments, 8);
  const Profile profile = profile_of(shape, segments);
  TriangleSurface surface;
  int previous = -1;
  for (std::size_t k = 0; k < profile.size(); ++k) {
    const int ring = add_ring(surface, profile[k], segments);
    if (k > 0)
      add_band(surface, previous, profile[k - 1].rho == 0, ring, profile[k].rho == 0, segments);
    previous = ring;
  }
  return surface;
}

}  // namespace mrsim
