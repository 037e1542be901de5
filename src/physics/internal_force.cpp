#include "physics/internal_force.hpp"

#include <algorithm>

#include "core/parallel.hpp"
#include "physics/green_nodal_forces.hpp"
#include "physics/stress.hpp"

namespace mrsim {

namespace {

void cauchy_gather(const LevelModel& m, IndexSet points, const Vec3* u, const Vec3* v, Vec3* f) {
  const int n = points.count;
  const bool damped = !m.D.empty();
  const int* start = m.adj.nbr_start.data();
  const int* nbr = m.adj.nbr.data();
  parallel_for(n, [&](int k) {
    const int i = points[k];
    Vec3 fi = Vec3::Zero();
    const Vec3 ui = u[i];
    for (int e = start[i]; e < start[i + 1]; ++e) fi.noalias() -= m.K[e] * (u[nbr[e]] - ui);
    if (damped) {
      const Vec3 vi = v[i];
      for (int e = start[i]; e < start[i + 1]; ++e) fi.noalias() -= m.D[e] * (v[nbr[e]] - vi);
    }
    f[i] = fi;
  });
}

// Per-tet nodal forces -V P ∇N_a (P = σ + ν for Cauchy); the sum over a is zero up to rounding.
inline void tet_nodal_forces(const LevelModel& m, int t, const Vec3* u, const Vec3* v,
                             TetGradients& out) {
  const TetGradients& g = m.geo.grad[t];
  const Tet& tet = m.geo.tets[t];
  const Mat3 G = tet_gradient(g, tet, u);
  const bool green = m.law.strain == StrainMeasure::GreenLagrange;
  const StiffnessScales& s = m.geo.scales_of(t, m.law.scales);
  Mat3 P;
  if (m.law.damped()) {
    const Mat3 Gd = tet_gradient(g, tet, v);
    P = green ? green_piola(G, &Gd, m.law, s) : cauchy_stress(G, &Gd, m.law, s);
  } else {
    P = green ? green_piola(G, nullptr, m.law, s) : cauchy_stress(G, nullptr, m.law, s);
  }
  P *= -m.geo.volume[t];
  for (int a = 0; a < 4; ++a) out[a].noalias() = P * g[a];
}

// Each tet's nodal forces are added to its vertices as soon as they are computed, so they never
// go through memory (issue 17 point 4). Tet lists are ascending (live_tets(), the level's own
// order), so each point receives its terms in the order of its incidence list, which is the
// gather's order: the same bits as the stored pass and gather below. One thread, either strain
// measure (Cauchy comes here only for the weighted interface pass).
void tet_pass_and_scatter(const LevelModel& m, IndexSet points, IndexSet tets,
                          const double* weight, const Vec3* u, const Vec3* v, Vec3* f,
                          ForceWorkspace& ws) {
  ws.reserve_for(m);
  const int* ids = tets.ids ? tets.ids : ws.all_tets.data();
  const bool every_point = !points.ids && points.count == m.num_points();
  const bool packed = ws.packed.packs(tets);
  // A closed packed list's vertices are all among `points` (PackedTets::closed): no mask.
  const bool unmasked = every_point || (packed && ws.packed.closed);
  unsigned char* mask = unmasked ? nullptr : ws.point_mask.data();
  for (int k = 0; k < points.count; ++k) {
    f[points[k]] = Vec3::Zero();
    if (mask) mask[points[k]] = 1;
  }
  if (m.law.strain == StrainMeasure::GreenLagrange) {
    if (packed)
      green_scatter_packed(m, ws.packed, u, v, weight, mask, f);
    else
      green_scatter_forces(m, ids, tets.count, u, v, weight, mask, f);
  } else {
    TetGradients tf;
    for (int q = 0; q < tets.count; ++q) {
      const int t = ids[q];
      if (weight && weight[t] == 0) continue;
      tet_nodal_forces(m, t, u, v, tf);
      for (int a = 0; a < 4; ++a) {
        const int p = m.geo.tets[t][a];
        if (mask && !mask[p]) continue;
        if (weight)
          f[p] += weight[t] * tf[a];
        else
          f[p] += tf[a];
      }
    }
  }
  if (mask)
    for (int k = 0; k < points.count; ++k) mask[points[k]] = 0;
}

// Green–Lagrange on several threads: thread c owns the points of its share of `points`
// (ascending: an id range [first, last)) and passes, in list order, every tet with a vertex
// there, adding forces to its own points only. Each point still receives its terms in
// ascending tet order from one thread: the same bits as one thread. Tets across two ranges are
// passed by both (few when the mesh is numbered compactly).
void threaded_green_scatter(const LevelModel& m, IndexSet points, IndexSet tets,
                            const double* weight, const Vec3* u, const Vec3* v, Vec3* f,
                            ForceWorkspace& ws) {
#ifndef _OPENMP
  return tet_pass_and_scatter(m, points, tets, weight, u, v, f, ws);
#else
  ws.reserve_for(m);
  const int* ids = tets.ids ? tets.ids : ws.all_tets.data();
  const bool every_point = !points.ids && points.count == m.num_points();
  unsigned char* mask = every_point ? nullptr : ws.point_mask.data();
  ws.thread_tets.resize(omp_get_max_threads());
  const int n = points.count;
#pragma omp parallel
  {
    const int threads = omp_get_num_threads(), c = omp_get_thread_num();
    const int lo = static_cast<int>(static_cast<long long>(n) * c / threads);
    const int hi = static_cast<int>(static_cast<long long>(n) * (c + 1) / threads);
    const int first = lo < n ? points[lo] : m.num_points();
    const int last = c + 1 < threads && hi < n ? points[hi] : m.num_points();
    for (int k = lo; k < hi; ++k) {
      f[points[k]] = Vec3::Zero();
      if (mask) mask[points[k]] = 1;
    }
    std::vector<int>& mine = ws.thread_tets[c];
    mine.clear();
    for (int q = 0; q < tets.count; ++q) {
      const Tet& t = m.geo.tets[ids[q]];
      for (int a = 0; a < 4; ++a)
        if (t[a] >= first && t[a] < last) {
          mine.push_back(ids[q]);
          break;
        }
    }
    green_scatter_forces(m, mine.data(), static_cast<int>(mine.size()), u, v, weight, mask, f,
                         first, last);
    if (mask)
      for (int k = lo; k < hi; ++k) mask[points[k]] = 0;
  }
#endif
}

// Several threads where the scatter does not serve (Cauchy's weighted interface pass, points
// not ascending): one pass over `tets` storing the per-tet forces, then a per-point gather
// over the incident tets (each weighted by weight[t] when given), in incidence order.
void stored_pass_and_gather(const LevelModel& m, IndexSet points, IndexSet tets,
                            const double* weight, const Vec3* u, const Vec3* v, Vec3* f,
                            ForceWorkspace& ws) {
  const int nt = tets.count;
  const int n = points.count;
  ws.reserve_for(m, true);
  TetGradients* tf = ws.tet_force.data();
  const int* ids = tets.ids ? tets.ids : ws.all_tets.data();
  const auto gather = [&](int k) {
    const int i = points[k];
    Vec3 fi = Vec3::Zero();
    for (int s = m.adj.inc_start[i]; s < m.adj.inc_start[i + 1]; ++s) {
      const int t = m.adj.inc_tet[s];
      if (!weight)
        fi += tf[t][m.adj.inc_local[s]];
      else if (weight[t] != 0)
        fi += weight[t] * tf[t][m.adj.inc_local[s]];
    }
    f[i] = fi;
  };
#pragma omp parallel
  {
#pragma omp for schedule(static)
    for (int q = 0; q < nt; ++q) tet_nodal_forces(m, ids[q], u, v, tf[ids[q]]);
#pragma omp for schedule(static)
    for (int k = 0; k < n; ++k) gather(k);
  }
}

// The per-tet pass and the sum over each point's tets, by whichever of the three forms above
// suits the thread count and the strain measure: the same bits from each.
void tet_pass(const LevelModel& m, IndexSet points, IndexSet tets, const double* weight,
              const Vec3* u, const Vec3* v, Vec3* f, ForceWorkspace& ws) {
  if (!use_threads(points.count)) return tet_pass_and_scatter(m, points, tets, weight, u, v, f, ws);
  // The threads' point ranges need the points ascending (every caller's lists are: sorted
  // active lists and their merges); otherwise the stored pass, slower, with the same bits.
  if (m.law.strain == StrainMeasure::GreenLagrange &&
      (!points.ids || std::is_sorted(points.ids, points.ids + points.count)))
    return threaded_green_scatter(m, points, tets, weight, u, v, f, ws);
  stored_pass_and_gather(m, points, tets, weight, u, v, f, ws);
}

}  // namespace

void ForceWorkspace::reserve_for(const LevelModel& model, bool per_tet) {
  if (all_tets.size() != model.geo.tets.size()) {
    point_mask.assign(model.num_points(), 0);
    all_tets.resize(model.geo.tets.size());
    for (size_t t = 0; t < all_tets.size(); ++t) all_tets[t] = static_cast<int>(t);
  }
  if (per_tet && tet_force.size() != model.geo.tets.size()) tet_force.resize(model.geo.tets.size());
}

void internal_forces(const LevelModel& model, const Vec3* u, const Vec3* v, Vec3* f,
                     ForceWorkspace& ws) {
  internal_forces(model, IndexSet::all(model.num_points()), IndexSet::all(model.num_tets()), u, v,
                  f, ws);
}

void internal_forces(const LevelModel& model, IndexSet points, IndexSet tets, const Vec3* u,
                     const Vec3* v, Vec3* f, ForceWorkspace& ws) {
  if (model.law.strain == StrainMeasure::Cauchy)
    cauchy_gather(model, points, u, v, f);
  else
    tet_pass(model, points, tets, nullptr, u, v, f, ws);
}

void weighted_internal_forces(const LevelModel& model, IndexSet points, IndexSet tets,
                              const double* tet_weight, const Vec3* u, const Vec3* v, Vec3* f,
                              ForceWorkspace& ws) {
  tet_pass(model, points, tets, tet_weight, u, v, f, ws);
}

void live_tets(const LevelModel& m, IndexSet points, std::vector<unsigned char>& mark,
               std::vector<int>& out) {
  out.clear();
  for (int k = 0; k < points.count; ++k) {
    const int i = points[k];
    for (int s = m.adj.inc_start[i]; s < m.adj.inc_start[i + 1]; ++s)
      if (!mark[m.adj.inc_tet[s]]) {
        mark[m.adj.inc_tet[s]] = 1;
        out.push_back(m.adj.inc_tet[s]);
      }
  }
  for (int t : out) mark[t] = 0;
  std::sort(out.begin(), out.end());
}

Vec3 point_internal_force(const LevelModel& m, int i, const Vec3* u, const Vec3* v) {
  Vec3 fi = Vec3::Zero();
  for (int s = m.adj.inc_start[i]; s < m.adj.inc_start[i + 1]; ++s) {
    const int t = m.adj.inc_tet[s];
    const TetGradients& g = m.geo.grad[t];
    const Mat3 G = tet_gradient(g, m.geo.tets[t], u);
    const Mat3 Gd = tet_gradient(g, m.geo.tets[t], v);
    const Mat3* gd = m.law.damped() ? &Gd : nullptr;
    const StiffnessScales& sc = m.geo.scales_of(t, m.law.scales);
    const Mat3 P = m.law.strain == StrainMeasure::GreenLagrange ? green_piola(G, gd, m.law, sc)
                                                                : cauchy_stress(G, gd, m.law, sc);
    fi -= m.geo.volume[t] * (P * g[m.adj.inc_local[s]]);
  }
  return fi;
}

double elastic_energy(const LevelModel& m, const Vec3* u) {
  double energy = 0;
  for (int t = 0; t < m.num_tets(); ++t) {
    const Mat3 G = tet_gradient(m.geo.grad[t], m.geo.tets[t], u);
    const Mat3 E = m.law.strain == StrainMeasure::GreenLagrange ? green_strain(G) : cauchy_strain(G);
    energy += m.geo.volume[t] * energy_density(E, m.law, m.geo.scales_of(t, m.law.scales));
  }
  return energy;
}

}  // namespace mrsim
