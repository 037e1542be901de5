#include "simulation/diagnostics.hpp"

#include <algorithm>

namespace mrsim {

double kinetic_energy(const PointState& s, const std::vector<double>& mass) {
  double e = 0;
  for (int i = 0; i < s.size(); ++i) e += 0.5 * mass[i] * s.v[i].squaredNorm();
  return e;
}

double internal_kinetic_energy(const PointState& s, const std::vector<double>& mass) {
  double m = 0;
  for (double mi : mass) m += mi;
  const Vec3 vcm = linear_momentum(s, mass) / m;
  double e = 0;
  for (int i = 0; i < s.size(); ++i) e += 0.5 * mass[i] * (s.v[i] - vcm).squaredNorm();
  return e;
}

Vec3 linear_momentum(const PointState& s, const std::vector<double>& mass) {
  Vec3 p = Vec3::Zero();
  for (int i = 0; i < s.size(); ++i) p += mass[i] * s.v[i];
  return p;
}

Vec3 angular_momentum(const PointState& s, const std::vector<double>& mass, const TetMesh& mesh) {
  Vec3 l = Vec3::Zero();
  for (int i = 0; i < s.size(); ++i) l += mass[i] * (mesh.points[i] + s.u[i]).cross(s.v[i]);
  return l;
}

Vec3 centre_of_mass(const TetMesh& mesh, const std::vector<double>& mass) {
  Vec3 c = Vec3::Zero();
  double m = 0;
  for (size_t i = 0; i < mass.size(); ++i) {
    c += mass[i] * mesh.points[i];
    m += mass[i];
  }
  return c / m;
}

double max_displacement(const PointState& s) {
  double d = 0;
  for (const Vec3& u : s.u) d = std::max(d, u.norm());
  return d;
}

}  // namespace mrsim
