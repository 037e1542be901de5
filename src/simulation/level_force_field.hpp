#pragma once
// Total force on the simulated points of one level: internal (elastic + damping) + gravity.
// With a point list (the level's active points) it costs O(active + their tets).
// Coupled to a hierarchy (energy-consistent coupling, docs/hierarchy.md), it also gathers the
// force on the level's ghosts, each tet weighted by its active share, for the transfer to the
// ghosts' sources (hierarchy/ghost_force_transfer.hpp): O(active + ghosts + live tets).
#include "hierarchy/status_lists.hpp"
#include "physics/internal_force.hpp"
#include "time/force_field.hpp"

namespace mrsim {

/// What one sub-step evaluates on a level when particles have their own time levels
/// (method.md §5.4): the integrated points (`served`: gravity and loads are added there), the
/// points whose force is gathered (served + the ghosts whose force reaches them, energy
/// coupling) and the tets those need. All sorted.
struct FieldSubset {
  std::vector<int> served, gathered, tets;
};

/// out = a ∪ b, list by list (sorted, no duplicate). No allocation once out has grown.
void merge_subsets(const FieldSubset& a, const FieldSubset& b, FieldSubset& out);

class LevelForceField final : public ForceField {
 public:
  LevelForceField(const LevelModel& model, const Vec3& gravity);
  /// Restrict to these points (nullptr: every point). The list is read at every evaluation;
  /// call refresh_tets() whenever it changes.
  void serve(const std::vector<int>* points);
  /// Energy-consistent coupling with the other levels of `h` (serves lists->active(level)).
  void couple(const Hierarchy* h, const StatusLists* lists, int level);
  void refresh_tets();
  /// Extra force per point (N, the level's surface loads), added on the served points; the
  /// array is read at every evaluation. nullptr: none.
  void set_external(const Vec3* external) { external_ = external; }
  /// Gravity m_p g on these points from now on, m_p the gravitational mass of
  /// hierarchy/interface_inertia.hpp (the lumped mass by default).
  void weigh(const std::vector<int>& points, const std::vector<PointInertia>& inertia);
  std::int64_t evaluate(const Vec3* u, const Vec3* v, Vec3* f) override;
  /// Per-tet stress evaluations of every evaluate() so far (the Green–Lagrange and weighted
  /// tet passes; Cauchy without ghosts gathers per edge and makes none): the kernel's work.
  std::int64_t tet_updates() const { return tet_updates_; }
  void set_tet_updates(std::int64_t n) { tet_updates_ = n; }  // a checkpoint's

  /// Fills `out` for these integrated points (a subset of the served ones) and the ghosts of
  /// this level whose force reaches them (sorted). O(their incident tets).
  void subset_for(const std::vector<int>& served, const std::vector<int>& ghosts,
                  FieldSubset& out);
  /// Evaluate only `subset` from now on (nullptr: every served point, the default).
  void use(const FieldSubset* subset) { subset_ = subset; }

  /// Coupled mode: does this level have ghosts (then its tets are weighted)? Its live tets and
  /// their weights (active shares after refresh_tets(); hierarchy/patch_test_weights.hpp may
  /// adjust them before the next evaluation).
  bool weighted() const { return weighted_; }
  const std::vector<int>& tets() const { return tets_; }
  /// tets() when they are the tets with a served vertex, kept since refresh_tets() (sorted):
  /// coupled, or Green–Lagrange; nullptr when this field keeps no such list (Cauchy alone).
  const std::vector<int>* kept_live_tets() const {
    return hierarchy_ || (points_ && model_.law.strain == StrainMeasure::GreenLagrange) ? &tets_
                                                                                       : nullptr;
  }
  const std::vector<double>& tet_weights() const { return share_; }
  /// For hierarchy/patch_test_weights.hpp: the weights to adjust, before the next evaluation
  /// (the packed pass gathers them again then).
  std::vector<double>& edit_tet_weights() {
    ws_.packed.weight_source = nullptr;
    return share_;
  }

 private:
  IndexSet points() const;
  void refresh_coupling();
  const LevelModel& model_;
  const std::vector<int>* points_ = nullptr;
  std::vector<int> tets_;                 // live tets when restricted
  std::vector<unsigned char> tet_mark_;
  std::vector<Vec3> weight_;              // m_i g, precomputed
  Vec3 gravity_;
  ForceWorkspace ws_;
  const Vec3* external_ = nullptr;
  // Coupled mode: used only while the level has ghosts (otherwise every live tet is whole).
  const Hierarchy* hierarchy_ = nullptr;
  const StatusLists* lists_ = nullptr;
  int level_ = 0;
  bool weighted_ = false;
  std::vector<int> gathered_;             // active ∪ ghosts, sorted
  std::vector<double> share_;             // per tet, 0 outside tets_
  const FieldSubset* subset_ = nullptr;
  std::int64_t tet_updates_ = 0;
};

}  // namespace mrsim
