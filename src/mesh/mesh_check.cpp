#include "mesh/mesh_check.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/log.hpp"
#include "mesh/mesh_input.hpp"

namespace mrsim {
namespace {

std::string plural(const std::string& noun) {
  if (noun == "vertex") return "vertices";
  if (noun == "tetrahedron") return "tetrahedra";
  return noun + "s";
}

std::string count_of(std::size_t n, const std::string& noun) {
  return cat(n, " ", n == 1 ? noun : plural(noun));
}

// "nodes 12, 12, 5, 6": a tet named by the file's own vertex numbering.
std::string tet_vertices(const RawMesh& raw, const Tet& t) {
  return cat(plural(raw.point_noun), " ", raw.point_ids[t[0]], ", ", raw.point_ids[t[1]], ", ",
             raw.point_ids[t[2]], ", ", raw.point_ids[t[3]]);
}

void require_tets(const RawMesh& raw, const std::filesystem::path& path) {
  if (!raw.tets.empty()) return;
  std::string what;
  for (const auto& [kind, n] : raw.ignored) what += cat(what.empty() ? "" : ", ", n, " ", kind);
  throw mesh_error(path, cat("contains no tetrahedra", what.empty() ? "" : cat(" (only ", what, ")"),
                             ": a volume mesh is needed"));
}

void require_finite_points(const RawMesh& raw, const std::filesystem::path& path) {
  for (std::size_t i = 0; i < raw.points.size(); ++i) {
    const Vec3& p = raw.points[i];
    if (!p.allFinite())
      throw mesh_error(path, cat(raw.point_noun, " ", raw.point_ids[i], " has a non-finite coordinate (",
                                 p.x(), ", ", p.y(), ", ", p.z(), ")"));
  }
}

// Readers check indices in the file's numbering; this repeats the range check so that no
// reader bug can ever index outside `points`, and rejects tets that use a vertex twice.
void require_valid_tet_vertices(const RawMesh& raw, const std::filesystem::path& path) {
  const auto n = static_cast<std::int64_t>(raw.points.size());
  for (std::size_t k = 0; k < raw.tets.size(); ++k) {
    const Tet& t = raw.tets[k];
    for (int v : t)
      if (v < 0 || v >= n)
        throw mesh_error(path, cat(raw.tet_noun, " ", raw.tet_ids[k], " refers to ", raw.point_noun, " index ", v,
                                   " (0-based), but the file has ", count_of(raw.points.size(), raw.point_noun)));
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        if (t[a] == t[b])
          throw mesh_error(path, cat(raw.tet_noun, " ", raw.tet_ids[k], " uses ", raw.point_noun, " ",
                                     raw.point_ids[t[a]], " twice (", tet_vertices(raw, t), ")"));
  }
}

// |6V| / (longest edge)^3: zero for flat or collapsed tets whatever the mesh size or unit.
double tet_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, double six_volume) {
  const Vec3 e[6] = {b - a, c - a, d - a, c - b, d - b, d - c};
  double longest2 = 0;
  for (const Vec3& v : e) longest2 = std::max(longest2, v.squaredNorm());
  if (longest2 == 0) return 0;
  return std::abs(six_volume) / (longest2 * std::sqrt(longest2));
}

void reject_degenerate_tets(const RawMesh& raw, const std::filesystem::path& path) {
  std::size_t bad = 0, first = 0;
  double first_quality = 0;
  for (std::size_t k = 0; k < raw.tets.size(); ++k) {
    const Tet& t = raw.tets[k];
    const Vec3 &a = raw.points[t[0]], &b = raw.points[t[1]], &c = raw.points[t[2]], &d = raw.points[t[3]];
    const double q = tet_quality(a, b, c, d, 6.0 * signed_volume(a, b, c, d));
    if (!(q >= kMinTetQuality)) {  // also catches a NaN quality from overflowing coordinates
      if (bad++ == 0) {
        first = k;
        first_quality = q;
      }
    }
  }
  if (bad == 0) return;
  throw mesh_error(path, cat(raw.tet_noun, " ", raw.tet_ids[first], " (", tet_vertices(raw, raw.tets[first]),
                             ") is degenerate: quality |6V|/(longest edge)^3 = ", short_number(first_quality),
                             " < ", short_number(kMinTetQuality), " (zero or near-zero volume)",
                             bad > 1 ? cat("; ", count_of(bad, raw.tet_noun), " are degenerate in total") : ""));
}

// Swapping two vertices flips the sign of the volume; mrsim requires V > 0 everywhere.
int reorient_inverted_tets(RawMesh& raw) {
  int flipped = 0;
  for (Tet& t : raw.tets)
    if (signed_volume(raw.points[t[0]], raw.points[t[1]], raw.points[t[2]], raw.points[t[3]]) < 0) {
      std::swap(t[2], t[3]);
      ++flipped;
    }
  return flipped;
}

// Compacts away vertices no tet uses (they would be massless, unconstrained points).
// Returns the loaded index -> file index map.
std::vector<int> remove_unreferenced_points(RawMesh& raw, std::vector<std::int64_t>& removed_ids) {
  std::vector<int> new_index(raw.points.size(), -1);
  for (const Tet& t : raw.tets)
    for (int v : t) new_index[v] = 0;
  std::vector<int> kept;
  kept.reserve(raw.points.size());
  for (std::size_t i = 0; i < raw.points.size(); ++i) {
    if (new_index[i] < 0) {
      removed_ids.push_back(raw.point_ids[i]);
      continue;
    }
    new_index[i] = static_cast<int>(kept.size());
    raw.points[kept.size()] = raw.points[i];
    raw.point_ids[kept.size()] = raw.point_ids[i];
    kept.push_back(static_cast<int>(i));
  }
  raw.points.resize(kept.size());
  raw.point_ids.resize(kept.size());
  if (!removed_ids.empty())
    for (Tet& t : raw.tets)
      for (int& v : t) v = new_index[v];
  return kept;
}

// With a report the caller prints its warnings (run.cpp does): printing here as well showed
// every warning twice (issue 18 defect 9).
void emit_warning(const std::string& message, MeshReadReport* report) {
  if (report)
    report->warnings.push_back(message);
  else
    warn(message);
}

std::string first_ids(const std::vector<std::int64_t>& ids) {
  constexpr std::size_t kShown = 5;
  std::string out;
  for (std::size_t i = 0; i < std::min(ids.size(), kShown); ++i) out += cat(i ? ", " : "", ids[i]);
  return ids.size() > kShown ? out + ", ..." : out;
}

}  // namespace

TetMesh check_raw_mesh(RawMesh raw, const std::filesystem::path& path, double metres_per_unit,
                       MeshReadReport* report) {
  require_tets(raw, path);
  require_finite_points(raw, path);
  require_valid_tet_vertices(raw, path);
  if (metres_per_unit != 1.0)
    for (Vec3& p : raw.points) p *= metres_per_unit;
  reject_degenerate_tets(raw, path);

  const int flipped = reorient_inverted_tets(raw);
  if (flipped > 0)
    emit_warning(cat(path.string(), ": ", flipped, " of ", count_of(raw.tets.size(), raw.tet_noun),
                     " had a negative volume (inverted) and were reoriented"),
                 report);

  std::vector<std::int64_t> removed;
  std::vector<int> kept = remove_unreferenced_points(raw, removed);
  if (!removed.empty())
    emit_warning(cat(path.string(), ": removed ", count_of(removed.size(), raw.point_noun), " used by no ",
                     raw.tet_noun, " (", plural(raw.point_noun), " ", first_ids(removed), ")"),
                 report);

  if (report) {
    report->format = raw.format;
    report->reoriented_tets = flipped;
    report->removed_vertices = static_cast<int>(removed.size());
    report->kept_vertices = std::move(kept);
    for (const auto& [kind, n] : raw.ignored) report->notes.push_back(cat("ignored ", n, " ", kind));
  }
  return TetMesh{std::move(raw.points), std::move(raw.tets)};
}

}  // namespace mrsim
