// The hierarchy's links and skin binding kept between runs (simulation/link_cache.hpp): a second
// set-up reads the very arrays build_level_links() and bind_skin() compute, without building a
// locator; other meshes or another skin are another key; a damaged file, or one whose indices
// leave their levels, is said, ignored and computed again.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <string>

#include "contact/skin.hpp"
#include "core/text_file.hpp"
#include "hierarchy/hierarchy_fixture.hpp"
#include "simulation/cache_folder.hpp"
#include "simulation/cached_payload.hpp"
#include "simulation/link_cache.hpp"

using namespace mrsim;

namespace {

// Three independent box meshes, the middle one shrunk by 3 % so that points of the levels
// beside it lie outside it (located by nearest tet, signed coordinates).
struct Levels : mrsim::testing::ThreeLevels {
  Levels() {
    for (Vec3& p : meshes[1].points) p = Vec3(0.05, 0.03, 0.02) + 0.97 * (p - Vec3(0.05, 0.03, 0.02));
  }
};

// Counts how often the locators are asked for, and builds them once.
struct CountingLocators {
  explicit CountingLocators(const std::vector<HierarchyLevel>& l) : levels(l) {}
  const std::vector<HierarchyLevel>& levels;
  int asked = 0;
  std::vector<TetLocator> built;
  LocatorSource source() {
    return [this]() -> const std::vector<TetLocator>& {
      ++asked;
      if (built.empty())
        for (const HierarchyLevel& l : levels) built.emplace_back(*l.mesh);
      return built;
    };
  }
};

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool same_lists(const CsrLists& a, const CsrLists& b) {
  return same_bytes(a.start, b.start) && same_bytes(a.items, b.items);
}

bool same_embedding(const Embedding& a, const Embedding& b) {
  return same_bytes(a.tet, b.tet) && same_bytes(a.bary, b.bary) && same_bytes(a.source, b.source);
}

void expect_same_links(const std::vector<LevelLinks>& a, const std::vector<LevelLinks>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t l = 0; l < a.size(); ++l) {
    EXPECT_TRUE(same_embedding(a[l].parent_tet, b[l].parent_tet)) << "level " << l;
    EXPECT_TRUE(same_embedding(a[l].child_tet, b[l].child_tet)) << "level " << l;
    EXPECT_TRUE(same_bytes(a[l].parent, b[l].parent)) << "level " << l;
    EXPECT_TRUE(same_lists(a[l].children, b[l].children)) << "level " << l;
    EXPECT_TRUE(same_lists(a[l].active_set, b[l].active_set)) << "level " << l;
    EXPECT_TRUE(same_lists(a[l].ghost_set, b[l].ghost_set)) << "level " << l;
    EXPECT_TRUE(same_lists(a[l].dependents, b[l].dependents)) << "level " << l;
  }
}

void expect_same_binding(const SkinBinding& a, const SkinBinding& b) {
  ASSERT_EQ(a.tet.size(), b.tet.size());
  for (std::size_t l = 0; l < a.tet.size(); ++l) {
    EXPECT_TRUE(same_bytes(a.tet[l], b.tet[l])) << "level " << l;
    EXPECT_TRUE(same_bytes(a.bary[l], b.bary[l])) << "level " << l;
  }
}


}  // namespace

TEST(LinkCache, ASecondSetUpReadsTheComputedLinksWithoutALocator) {
  CacheFolder folder("links");
  const Levels f;
  const std::vector<LevelLinks> computed = build_level_links(f.levels);
  // The shrunk level makes some points of the others outside it: the cache must keep their
  // extrapolating (negative) coordinates too.
  bool outside = false;
  for (const Bary& b : computed[2].parent_tet.bary)
    for (double x : b) outside |= x < -1e-6;
  ASSERT_TRUE(outside);

  CountingLocators first(f.levels), second(f.levels);
  bool reused = true;
  const auto cold = cached_level_links(f.levels, hierarchy_inputs(f.levels), first.source(), &reused);
  EXPECT_FALSE(reused);
  EXPECT_EQ(first.asked, 1);
  ASSERT_EQ(folder.files("links").size(), 1u);
  const auto warm = cached_level_links(f.levels, hierarchy_inputs(f.levels), second.source(), &reused);
  EXPECT_TRUE(reused);
  EXPECT_EQ(second.asked, 0) << "a cached hierarchy builds no locator";
  expect_same_links(cold, computed);
  expect_same_links(warm, computed);
}

TEST(LinkCache, OtherMeshesAreAnotherKey) {
  CacheFolder folder("links");
  Levels f;
  CountingLocators locators(f.levels);
  cached_level_links(f.levels, hierarchy_inputs(f.levels), locators.source());
  f.meshes[2].points[5].x() += 1e-12;
  bool reused = true;
  const auto moved = cached_level_links(f.levels, hierarchy_inputs(f.levels), locators.source(), &reused);
  EXPECT_FALSE(reused);
  EXPECT_EQ(folder.files("links").size(), 2u);
  // Two levels of the three: another hierarchy.
  std::vector<HierarchyLevel> two(f.levels.begin(), f.levels.begin() + 2);
  CountingLocators fewer(two);
  cached_level_links(two, hierarchy_inputs(two), fewer.source(), &reused);
  EXPECT_FALSE(reused);
}

TEST(LinkCache, ADamagedFileIsSaidIgnoredAndComputedAgain) {
  CacheFolder folder("links");
  const Levels f;
  const std::vector<LevelLinks> computed = build_level_links(f.levels);
  CountingLocators locators(f.levels);
  cached_level_links(f.levels, hierarchy_inputs(f.levels), locators.source());
  ASSERT_EQ(folder.files("links").size(), 1u);
  const std::filesystem::path file = folder.files("links")[0];
  const std::string good = read_text_if_any(file);
  struct Damage {
    const char* what;
    std::function<void()> apply;
    const char* said;
  };
  const std::vector<Damage> damages = {
      {"truncated", [&] { std::ofstream(file, std::ios::binary) << good.substr(0, good.size() / 2); },
       "damaged"},
      {"a flipped bit",
       [&] {
         std::string b = good;
         b[b.size() - 9] ^= 4;
         std::ofstream(file, std::ios::binary) << b;
       },
       "damaged"},
      {"not a result", [&] { std::ofstream(file, std::ios::binary) << "{\"key\": 1}"; },
       "not a result of this version"},
      // Level 0 has no coarser level: its parent tets are all -1. A 0 there, checksum and all,
      // would send a ghost to a level that does not exist.
      {"a parent tet on level 0",
       [&] {
         std::ofstream(file, std::ios::binary) << good;
         rewrite_payload(file, [](std::string& p) { std::memset(p.data() + 16, 0, sizeof(int)); });
       },
       "a link to a level that is not there"},
      // One byte past the last list.
      {"bytes after the record",
       [&] {
         std::ofstream(file, std::ios::binary) << good;
         rewrite_payload(file, [](std::string& p) { p += '\0'; });
       },
       "bytes after the record"},
  };
  for (const Damage& d : damages) {
    d.apply();
    ::testing::internal::CaptureStderr();
    bool reused = true;
    const auto links = cached_level_links(f.levels, hierarchy_inputs(f.levels), locators.source(), &reused);
    const std::string said = ::testing::internal::GetCapturedStderr();
    EXPECT_FALSE(reused) << d.what;
    EXPECT_NE(said.find("ignored the level links cache"), std::string::npos) << d.what << ": " << said;
    EXPECT_NE(said.find(d.said), std::string::npos) << d.what << ": " << said;
    expect_same_links(links, computed);
    cached_level_links(f.levels, hierarchy_inputs(f.levels), locators.source(), &reused);
    EXPECT_TRUE(reused) << "rewritten after " << d.what;
  }
}

TEST(LinkCache, TheSkinBindingIsKeptAndKeyedByTheSkin) {
  CacheFolder folder("skin_binding");
  const Levels f;
  const auto links = build_level_links(f.levels);
  const Skin skin = boundary_skin(f.meshes.back());
  const Embedding* finest = &links.back().parent_tet;
  CountingLocators computing(f.levels);
  const SkinBinding computed = bind_skin(skin, computing.source()(), finest);
  bool outside = false;
  for (const Bary& b : computed.bary[1])
    for (double x : b) outside |= x < -1e-6;
  ASSERT_TRUE(outside) << "the shrunk level extrapolates skin vertices";

  CountingLocators first(f.levels), second(f.levels);
  bool reused = true;
  const SkinBinding cold =
      cached_skin_binding(skin, f.levels, hierarchy_inputs(f.levels), finest, first.source(), &reused);
  EXPECT_FALSE(reused);
  const SkinBinding warm =
      cached_skin_binding(skin, f.levels, hierarchy_inputs(f.levels), finest, second.source(), &reused);
  EXPECT_TRUE(reused);
  EXPECT_EQ(second.asked, 0);
  expect_same_binding(cold, computed);
  expect_same_binding(warm, computed);

  // A given surface (no finest point behind each vertex) is another skin, as is a moved one.
  Skin given = skin;
  given.point.clear();
  cached_skin_binding(given, f.levels, hierarchy_inputs(f.levels), finest, second.source(), &reused);
  EXPECT_FALSE(reused);
  Skin moved = skin;
  moved.rest[0].z() += 1e-9;
  cached_skin_binding(moved, f.levels, hierarchy_inputs(f.levels), finest, second.source(), &reused);
  EXPECT_FALSE(reused);
  EXPECT_EQ(folder.files("skin_binding").size(), 3u);

  // A tet index beyond its level, checksum and all, is refused.
  for (const auto& kept : folder.files("skin_binding")) std::filesystem::remove(kept);
  cached_skin_binding(skin, f.levels, hierarchy_inputs(f.levels), finest, second.source());
  ASSERT_EQ(folder.files("skin_binding").size(), 1u);
  rewrite_payload(folder.files("skin_binding")[0], [](std::string& p) {
    const int beyond = 1 << 20;
    std::memcpy(p.data() + 16, &beyond, sizeof beyond);  // level 0, first vertex
  });
  ::testing::internal::CaptureStderr();
  const SkinBinding again =
      cached_skin_binding(skin, f.levels, hierarchy_inputs(f.levels), finest, second.source(), &reused);
  const std::string said = ::testing::internal::GetCapturedStderr();
  EXPECT_FALSE(reused);
  EXPECT_NE(said.find("a tet out of its level"), std::string::npos) << said;
  expect_same_binding(again, computed);
}
