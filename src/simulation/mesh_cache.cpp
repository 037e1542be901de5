#include "simulation/mesh_cache.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/byte_record.hpp"
#include "core/log.hpp"
#include "simulation/result_cache.hpp"

namespace mrsim {

namespace {

// Bumped whenever what the files hold changes (it is in the key with the build).
constexpr int kMeshRecordVersion = 1;
constexpr std::size_t kAnyCount = std::numeric_limits<std::size_t>::max();

bool is_vtu(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".vtu";
}

// The file's bytes read in blocks into one buffer on the stack and hashed as they come: a
// string of the whole file cost more in fresh pages than the hash (1 ms of a warm set-up).
// Nothing when it cannot be read or is empty (read_tet_mesh then says why, or reads nothing).
std::optional<std::uint64_t> content_hash(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  InputHash h;
  // A multiple of 8, as InputHash::bytes() steps: whole blocks hash as the whole file would (a
  // short read would give another key: one cache miss).
  std::array<char, 1 << 16> block;
  std::size_t total = 0;
  for (;;) {
    const ssize_t n = ::read(fd, block.data(), block.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ::close(fd);
      if (n < 0 || total == 0) return std::nullopt;
      h.value(total);
      return h.h;
    }
    h.bytes(block.data(), static_cast<std::size_t>(n));
    total += static_cast<std::size_t>(n);
  }
}

// The path too: the reader's warnings name it, and a copy elsewhere must say its own.
std::string key_of(const std::filesystem::path& path, std::uint64_t content, LengthUnit unit) {
  InputHash h;
  h.value(kMeshRecordVersion);
  const std::string name = path.string();
  h.value(name.size());
  h.bytes(name.data(), name.size());
  h.value(content);
  h.value(static_cast<int>(unit));
  h.build();  // the reader's checks and repairs are this build's
  return h.hex();
}

std::filesystem::path file_of(const std::string& key) {
  const std::filesystem::path dir = result_cache_dir("meshes");
  return dir.empty() ? dir : dir / ("mesh_" + key + ".bin");
}

void put_strings(ByteRecordWriter& w, const std::vector<std::string>& list) {
  w.value(static_cast<std::uint64_t>(list.size()));
  for (const std::string& s : list) w.array(std::vector<char>(s.begin(), s.end()));
}

std::vector<std::string> get_strings(ByteRecordReader& r) {
  const auto n = r.value<std::uint64_t>();
  std::vector<std::string> list;
  for (std::uint64_t k = 0; k < n; ++k) {  // each reads its bytes: a lying count runs out
    const std::vector<char> s = r.array<char>(kAnyCount);
    list.emplace_back(s.begin(), s.end());
  }
  return list;
}

std::string record_of(const TetMesh& mesh, const MeshReadReport& report) {
  ByteRecordWriter w;
  std::vector<std::array<double, 3>> points;  // Eigen's vectors are not trivially copyable
  points.reserve(mesh.points.size());
  for (const Vec3& p : mesh.points) points.push_back({p.x(), p.y(), p.z()});
  w.array(points);
  w.array(mesh.tets);
  w.array(std::vector<char>(report.format.begin(), report.format.end()));
  w.value(static_cast<std::int64_t>(report.reoriented_tets));
  w.value(static_cast<std::int64_t>(report.removed_vertices));
  w.array(report.kept_vertices);
  put_strings(w, report.warnings);
  put_strings(w, report.notes);
  return std::move(w).take();
}

void fail(const char* why) { throw std::runtime_error(why); }

// What every consumer of a TetMesh relies on (mesh/tet_mesh.hpp), checked again: the record's
// checksum catches damage, not a record this build would never have written.
void check_mesh(const TetMesh& m) {
  const auto n = static_cast<int>(m.points.size());
  for (const Vec3& p : m.points)
    if (!p.allFinite()) fail("a point that is not finite");
  for (const Tet& t : m.tets) {
    for (int v : t)
      if (v < 0 || v >= n) fail("a tet vertex out of the mesh");
    if (!(signed_volume(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]) > 0))
      fail("a tet that is not positively oriented");
  }
  if (m.tets.empty()) fail("no tets");
}

TetMesh read_record(std::string_view bytes, MeshReadReport& report) {
  ByteRecordReader r(bytes);
  TetMesh m;
  for (const auto& p : r.array<std::array<double, 3>>(kAnyCount))
    m.points.emplace_back(p[0], p[1], p[2]);
  m.tets = r.array<Tet>(kAnyCount);
  const std::vector<char> format = r.array<char>(kAnyCount);
  report.format.assign(format.begin(), format.end());
  report.reoriented_tets = static_cast<int>(r.value<std::int64_t>());
  report.removed_vertices = static_cast<int>(r.value<std::int64_t>());
  report.kept_vertices = r.array<int>(m.points.size());
  report.warnings = get_strings(r);
  report.notes = get_strings(r);
  r.expect_end();
  check_mesh(m);
  if (report.kept_vertices.size() != m.points.size()) fail("another mesh");
  return m;
}

// The caller's report, or warn() for each warning as read_tet_mesh does without one.
void hand_over(MeshReadReport&& read, MeshReadReport* report) {
  if (report) {
    *report = std::move(read);
    return;
  }
  for (const std::string& w : read.warnings) warn(w);
}

}  // namespace

TetMesh read_level_mesh(const std::filesystem::path& path, LengthUnit unit,
                        MeshReadReport* report, bool* reused) {
  if (reused) *reused = false;
  const bool keep = is_vtu(path) && !result_cache_dir("meshes").empty();
  const std::optional<std::uint64_t> content = keep ? content_hash(path) : std::nullopt;
  if (!content) return read_tet_mesh(path, unit, report);  // its errors, unkept
  const std::string key = key_of(path, *content, unit);
  const std::filesystem::path file = file_of(key);
  MeshReadReport read;
  std::optional<TetMesh> known;
  read_cached_bytes(file, key, "mesh", [&](std::string_view record) {
    MeshReadReport r;
    known = read_record(record, r);
    read = std::move(r);
  });
  if (known) {
    if (reused) *reused = true;
    hand_over(std::move(read), report);
    return std::move(*known);
  }
  TetMesh mesh = read_tet_mesh(path, unit, &read);
  // Kept only if the file did not change while VTK read it: else the record would hold another
  // mesh than its key's bytes.
  if (content_hash(path) == content) write_cached_bytes(file, key, record_of(mesh, read), "mesh");
  hand_over(std::move(read), report);
  return mesh;
}

}  // namespace mrsim
