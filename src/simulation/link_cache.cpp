#include "simulation/link_cache.hpp"

#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/byte_record.hpp"
#include "hierarchy/csr_lists.hpp"

namespace mrsim {

namespace {

// Bumped whenever what the files hold changes (it is in the key with the build).
constexpr int kLinksVersion = 1;
constexpr std::size_t kAnyCount = std::numeric_limits<std::size_t>::max();

std::string key_of(InputHash h, std::string_view kind) {
  h.bytes(kind.data(), kind.size());
  h.value(kLinksVersion);
  h.build();
  return h.hex();
}

std::filesystem::path file_of(std::string_view kind, const std::string& key) {
  const std::filesystem::path dir = result_cache_dir(kind);
  return dir.empty() ? dir : dir / (std::string(kind) + "_" + key + ".bin");
}

void fail(const char* why) { throw std::runtime_error(why); }

void put(ByteRecordWriter& w, const Embedding& e) {
  w.array(e.tet);
  w.array(e.bary);
  w.array(e.source);
}

void put(ByteRecordWriter& w, const CsrLists& c) {
  w.array(c.start);
  w.array(c.items);
}

// The embedding of a level's n points in `into` (none: the level has no such neighbour). Each
// tet must be one of `into`'s and each source its vertices, as embed() and none() make them.
Embedding get_embedding(ByteRecordReader& r, std::size_t n, const TetMesh* into) {
  Embedding e;
  e.tet = r.array<int>(n);
  e.bary = r.array<Bary>(n);
  e.source = r.array<std::array<int, 4>>(n);
  if (e.tet.size() != n || e.bary.size() != n || e.source.size() != n) fail("another mesh");
  const std::array<int, 4> nothing{-1, -1, -1, -1};
  for (std::size_t i = 0; i < n; ++i) {
    const int t = e.tet[i];
    if (!into) {
      if (t != -1 || e.source[i] != nothing) fail("a link to a level that is not there");
    } else if (t < 0 || t >= static_cast<int>(into->tets.size()) || e.source[i] != into->tets[t]) {
      fail("a tet out of its level");
    }
  }
  return e;
}

// Rows of points of the next finer level (`items_below` of them).
CsrLists get_lists(ByteRecordReader& r, std::size_t rows, int items_below) {
  CsrLists c;
  c.start = r.array<int>(rows + 1);
  c.items = r.array<int>(kAnyCount);
  if (!rows_add_up(c.start, rows, c.items.size())) fail("rows that do not add up");
  for (int p : c.items)
    if (p < 0 || p >= items_below) fail("a point out of its level");
  return c;
}

std::string links_record(const std::vector<LevelLinks>& links) {
  ByteRecordWriter w;
  w.value(static_cast<std::uint64_t>(links.size()));
  for (const LevelLinks& l : links) {
    put(w, l.parent_tet);
    put(w, l.child_tet);
    w.array(l.parent);
    for (const CsrLists* c : {&l.children, &l.active_set, &l.ghost_set, &l.dependents}) put(w, *c);
  }
  return std::move(w).take();
}

std::vector<LevelLinks> read_links(std::string_view bytes,
                                   const std::vector<HierarchyLevel>& levels) {
  ByteRecordReader r(bytes);
  const std::size_t L = levels.size();
  if (r.value<std::uint64_t>() != L) fail("another hierarchy");
  std::vector<LevelLinks> links(L);
  for (std::size_t l = 0; l < L; ++l) {
    const std::size_t n = levels[l].mesh->points.size();
    const TetMesh* coarser = l > 0 ? levels[l - 1].mesh : nullptr;
    const TetMesh* finer = l + 1 < L ? levels[l + 1].mesh : nullptr;
    LevelLinks& k = links[l];
    k.parent_tet = get_embedding(r, n, coarser);
    k.child_tet = get_embedding(r, n, finer);
    k.parent = r.array<int>(n);
    if (k.parent.size() != n) fail("another mesh");
    for (int p : k.parent)
      if (coarser ? p < 0 || p >= static_cast<int>(coarser->points.size()) : p != -1)
        fail("a parent out of its level");
    const int below = finer ? static_cast<int>(finer->points.size()) : 0;
    for (CsrLists* c : {&k.children, &k.active_set, &k.ghost_set, &k.dependents})
      *c = get_lists(r, n, below);
  }
  r.expect_end();
  return links;
}

std::string binding_record(const SkinBinding& b) {
  ByteRecordWriter w;
  w.value(static_cast<std::uint64_t>(b.tet.size()));
  for (std::size_t l = 0; l < b.tet.size(); ++l) {
    w.array(b.tet[l]);
    w.array(b.bary[l]);
  }
  return std::move(w).take();
}

SkinBinding read_binding(std::string_view bytes, std::size_t vertices,
                         const std::vector<HierarchyLevel>& levels) {
  ByteRecordReader r(bytes);
  if (r.value<std::uint64_t>() != levels.size()) fail("another hierarchy");
  SkinBinding b;
  for (const HierarchyLevel& level : levels) {
    b.tet.push_back(r.array<int>(vertices));
    b.bary.push_back(r.array<Bary>(vertices));
    if (b.tet.back().size() != vertices || b.bary.back().size() != vertices) fail("another skin");
    for (int t : b.tet.back())
      if (t < 0 || t >= static_cast<int>(level.mesh->tets.size())) fail("a tet out of its level");
  }
  r.expect_end();
  return b;
}

// The result `read` makes of the file kept under `key` in `kind`, or else `compute()`, stored
// (as `record` writes it) for the next run.
template <class Read, class Compute, class Record>
auto kept_or_computed(std::string_view kind, const InputHash& inputs, std::string_view what,
                      Read read, Compute compute, Record record, bool* reused) {
  const std::string key = key_of(inputs, kind);
  const std::filesystem::path file = file_of(kind, key);
  std::optional<decltype(compute())> known;
  read_cached_bytes(file, key, what, [&](std::string_view bytes) { known = read(bytes); });
  if (reused) *reused = known.has_value();
  if (known) return std::move(*known);
  auto computed = compute();
  write_cached_bytes(file, key, record(computed), what);
  return computed;
}

}  // namespace

InputHash hierarchy_inputs(const std::vector<HierarchyLevel>& levels) {
  InputHash h;
  h.value(levels.size());
  for (const HierarchyLevel& level : levels) h.mesh(*level.mesh);
  return h;
}

std::vector<LevelLinks> cached_level_links(const std::vector<HierarchyLevel>& levels,
                                           const InputHash& meshes, const LocatorSource& locators,
                                           bool* reused) {
  return kept_or_computed(
      "links", meshes, "level links",
      [&](std::string_view bytes) { return read_links(bytes, levels); },
      [&] { return build_level_links(levels, locators()); }, links_record, reused);
}

SkinBinding cached_skin_binding(const Skin& skin, const std::vector<HierarchyLevel>& levels,
                                const InputHash& meshes, const Embedding* finest_in_coarser,
                                const LocatorSource& locators, bool* reused) {
  // bind_skin() reads the skin's rest positions and, for a boundary skin, which finest point
  // each vertex is.
  InputHash h = meshes;
  h.value(skin.rest.size());
  if (!skin.rest.empty()) h.bytes(skin.rest.data(), skin.rest.size() * sizeof(Vec3));
  h.value(skin.point.size());
  if (!skin.point.empty()) h.bytes(skin.point.data(), skin.point.size() * sizeof(int));
  h.value(finest_in_coarser != nullptr);
  return kept_or_computed(
      "skin_binding", h, "skin binding",
      [&](std::string_view bytes) { return read_binding(bytes, skin.rest.size(), levels); },
      [&] { return bind_skin(skin, locators(), finest_in_coarser); }, binding_record, reused);
}

}  // namespace mrsim
