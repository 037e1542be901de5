#pragma once
// Total force on the simulated points of one level: internal (elastic + damping) + gravity.
// With a point list (the level's active points) it costs O(active + their tets).
#include "physics/internal_force.hpp"
#include "time/force_field.hpp"

namespace mrsim {

class LevelForceField final : public ForceField {
 public:
  LevelForceField(const LevelModel& model, const Vec3& gravity);
  /// Restrict to these points (nullptr: every point). The list is read at every evaluation;
  /// call refresh_tets() whenever it changes.
  void serve(const std::vector<int>* points);
  void refresh_tets();
  std::int64_t evaluate(const Vec3* u, const Vec3* v, Vec3* f) override;

 private:
  IndexSet points() const;
  const LevelModel& model_;
  const std::vector<int>* points_ = nullptr;
  std::vector<int> tets_;                 // live tets when restricted
  std::vector<unsigned char> tet_mark_;
  std::vector<Vec3> weight_;              // m_i g, precomputed
  ForceWorkspace ws_;
};

}  // namespace mrsim
