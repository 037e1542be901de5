#include "simulation/level_array_cache.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "core/byte_record.hpp"
#include "hierarchy/csr_lists.hpp"
#include "simulation/result_cache.hpp"

namespace mrsim {

namespace {

// Bumped whenever what the files hold changes (it is in the key with the build).
constexpr int kArraysVersion = 1;
constexpr std::size_t kAnyCount = std::numeric_limits<std::size_t>::max();

std::string key_of(const std::string& spectra_key) {
  InputHash h;
  h.bytes(spectra_key.data(), spectra_key.size());
  h.value(kArraysVersion);
  return h.hex();
}

std::filesystem::path file_of(const std::string& key) {
  const std::filesystem::path dir = result_cache_dir("level_arrays");
  return dir.empty() ? dir : dir / ("level_arrays_" + key + ".bin");
}

void fail(const char* why) { throw std::runtime_error(why); }

void check_rows(const std::vector<int>& start, std::size_t n, std::size_t items) {
  if (!rows_add_up(start, n, items)) fail("rows that do not add up");
}

// Each point's neighbours ascending, other points of the mesh; each incidence a tet of the mesh
// that has the point at that local index.
void check_adjacency(const PointAdjacency& a, const TetMesh& mesh) {
  const std::size_t n = mesh.points.size();
  check_rows(a.nbr_start, n, a.nbr.size());
  check_rows(a.inc_start, n, a.inc_tet.size());
  if (a.inc_local.size() != a.inc_tet.size()) fail("rows that do not add up");
  for (std::size_t i = 0; i < n; ++i) {
    for (int s = a.nbr_start[i]; s < a.nbr_start[i + 1]; ++s) {
      const int j = a.nbr[s];
      if (j < 0 || j >= static_cast<int>(n) || j == static_cast<int>(i) ||
          (s > a.nbr_start[i] && j <= a.nbr[s - 1]))
        fail("a neighbour out of its level");
    }
    for (int s = a.inc_start[i]; s < a.inc_start[i + 1]; ++s) {
      const int t = a.inc_tet[s], k = a.inc_local[s];
      if (t < 0 || t >= static_cast<int>(mesh.tets.size()) || k < 0 || k > 3 ||
          mesh.tets[t][k] != static_cast<int>(i))
        fail("a tet that is not the point's");
    }
  }
}

void check_values(const std::vector<double>& v, std::size_t n, bool nonnegative) {
  if (v.size() != n) fail("another mesh");
  for (double x : v)
    if (!std::isfinite(x) || (nonnegative && x < 0)) fail("a value out of range");
}

LevelArrays read_record(std::string_view bytes, const TetMesh& mesh) {
  ByteRecordReader r(bytes);
  const std::size_t n = mesh.points.size(), tets = mesh.tets.size();
  LevelArrays a;
  a.adj.nbr_start = r.array<int>(n + 1);
  a.adj.nbr = r.array<int>(kAnyCount);
  a.adj.inc_start = r.array<int>(n + 1);
  a.adj.inc_tet = r.array<int>(4 * tets);
  a.adj.inc_local = r.array<std::int8_t>(4 * tets);
  a.laplacian_w = r.array<double>(kAnyCount);
  a.bounds.stiffness = r.array<double>(tets);
  a.bounds.damping = r.array<double>(tets);
  r.expect_end();
  check_adjacency(a.adj, mesh);
  check_values(a.laplacian_w, a.adj.nbr.size(), false);
  check_values(a.bounds.stiffness, tets, true);
  check_values(a.bounds.damping, tets, true);
  return a;
}

}  // namespace

std::optional<LevelArrays> read_level_arrays(const std::string& key, const TetMesh& mesh) {
  const std::string k = key_of(key);
  std::optional<LevelArrays> known;
  read_cached_bytes(file_of(k), k, "level arrays",
                    [&](std::string_view bytes) { known = read_record(bytes, mesh); });
  return known;
}

void write_level_arrays(const std::string& key, const LevelModel& m) {
  ByteRecordWriter w;
  w.array(m.adj.nbr_start);
  w.array(m.adj.nbr);
  w.array(m.adj.inc_start);
  w.array(m.adj.inc_tet);
  w.array(m.adj.inc_local);
  w.array(m.laplacian_w);
  w.array(m.bounds.stiffness);
  w.array(m.bounds.damping);
  const std::string k = key_of(key);
  write_cached_bytes(file_of(k), k, std::move(w).take(), "level arrays");
}

}  // namespace mrsim
