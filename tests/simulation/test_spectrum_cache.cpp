// The levels' spectra kept between runs (simulation/spectrum_cache.hpp): a second build of the
// same level reads them and is the same model, bit for bit; any input they read changes the key;
// a damaged file is said, ignored and rewritten; a folder that cannot be written costs a warning.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "simulation/cache_folder.hpp"
#include "simulation/result_cache.hpp"
#include "simulation/small_level.hpp"
#include "simulation/spectrum_cache.hpp"
#include "support/same_bits.hpp"

using namespace mrsim;

namespace {

TetMesh box() { return test::small_box(); }
MaterialLaw law() { return test::damped_law(); }

std::vector<std::uint8_t> held(const TetMesh& mesh) {
  std::vector<std::uint8_t> h(mesh.points.size(), 0);
  for (size_t i = 0; i < h.size(); ++i) h[i] = mesh.points[i].x() < 1e-9;
  return h;
}

using test::same_bits;

// n results <prefix><k><ext> of `size` bytes (sparse: no disk) in `dir`, the k-th written
// `hours` − k hours ago: the oldest first.
void aged_results(const std::filesystem::path& dir, const std::string& prefix,
                  const std::string& ext, int n, std::uintmax_t size, int hours) {
  std::filesystem::create_directories(dir);
  const auto now = std::filesystem::file_time_type::clock::now();
  for (int k = 0; k < n; ++k) {
    const std::filesystem::path f = dir / (prefix + std::to_string(k) + ext);
    std::ofstream(f).close();
    std::filesystem::resize_file(f, size);
    std::filesystem::last_write_time(f, now - std::chrono::hours(hours - k));
  }
}

}  // namespace

TEST(SpectrumCache, ASecondBuildReadsTheSpectraAndIsTheSameModel) {
  CacheFolder folder("spectra");
  const TetMesh mesh = box();
  bool reused = true;
  const LevelModel first = cached_level_model(mesh, law(), false, held(mesh), &reused);
  EXPECT_FALSE(reused);
  ASSERT_EQ(folder.files("spectra").size(), 1u);
  const LevelModel second = cached_level_model(mesh, law(), false, held(mesh), &reused);
  EXPECT_TRUE(reused);
  EXPECT_TRUE(second.K.empty());  // Green–Lagrange, explicit: nothing else reads K
  for (auto [a, b] : {std::pair{level_spectra(first).stiffness, level_spectra(second).stiffness},
                      std::pair{level_spectra(first).damping, level_spectra(second).damping},
                      std::pair{level_spectra(first).combined, level_spectra(second).combined},
                      std::pair{first.stiffness_spectrum.scale, second.stiffness_spectrum.scale},
                      std::pair{first.step_damping_scale, second.step_damping_scale},
                      std::pair{first.time_level_damping_scale,
                                second.time_level_damping_scale}})
    EXPECT_TRUE(same_bits(a, b));
  EXPECT_TRUE(std::isfinite(level_spectra(first).combined));
  // Undamped: the combined limit is infinite, and comes back so.
  MaterialLaw undamped = law();
  undamped.psi = 0;
  cached_level_model(mesh, undamped, false, held(mesh));
  const LevelModel again = cached_level_model(mesh, undamped, false, held(mesh), &reused);
  EXPECT_TRUE(reused);
  EXPECT_TRUE(std::isinf(level_spectra(again).combined));
}

TEST(SpectrumCache, EveryInputChangesTheKey) {
  const TetMesh mesh = box();
  const std::string key = spectrum_key(mesh, law(), false, held(mesh));
  EXPECT_EQ(key.size(), 16u);
  EXPECT_EQ(key, spectrum_key(mesh, law(), false, held(mesh)));
  EXPECT_NE(key, spectrum_key(mesh, law(), true, held(mesh)));
  EXPECT_NE(key, spectrum_key(mesh, law(), false, {}));
  MaterialLaw other = law();
  other.psi = 5.5;
  EXPECT_NE(key, spectrum_key(mesh, other, false, held(mesh)));
  other = law();
  other.strain = StrainMeasure::Cauchy;
  EXPECT_NE(key, spectrum_key(mesh, other, false, held(mesh)));
  other = law();
  other.scales.mu[4] = 1.1;
  EXPECT_NE(key, spectrum_key(mesh, other, false, held(mesh)));
  TetMesh moved = mesh;
  moved.points[3].y() += 1e-12;
  EXPECT_NE(key, spectrum_key(moved, law(), false, held(mesh)));
}

TEST(SpectrumCache, ADamagedFileIsSaidIgnoredAndRewritten) {
  CacheFolder folder("spectra");
  const TetMesh mesh = box();
  const LevelModel first = cached_level_model(mesh, law(), false, held(mesh));
  ASSERT_EQ(folder.files("spectra").size(), 1u);
  for (const char* damage : {"{\"key\": ", "{\"key\": \"0000000000000000\"}"}) {
    { std::ofstream(folder.files("spectra")[0]) << damage; }
    ::testing::internal::CaptureStderr();
    bool reused = true;
    const LevelModel m = cached_level_model(mesh, law(), false, held(mesh), &reused);
    const std::string said = ::testing::internal::GetCapturedStderr();
    EXPECT_FALSE(reused) << damage;
    EXPECT_NE(said.find("ignored the level spectra cache"), std::string::npos) << said;
    EXPECT_TRUE(same_bits(m.step_damping_scale, first.step_damping_scale));
    cached_level_model(mesh, law(), false, held(mesh), &reused);
    EXPECT_TRUE(reused) << "rewritten after " << damage;
  }
}

TEST(SpectrumCache, AFolderThatCannotBeWrittenCostsAWarning) {
  const char* old = std::getenv("MRSIM_CACHE_DIR");
  const std::string saved = old ? old : "";
  ::setenv("MRSIM_CACHE_DIR", "/dev/null/mrsim", 1);
  const TetMesh mesh = box();
  ::testing::internal::CaptureStderr();
  bool reused = true;
  const LevelModel m = cached_level_model(mesh, law(), false, held(mesh), &reused);
  const std::string said = ::testing::internal::GetCapturedStderr();
  EXPECT_FALSE(reused);
  EXPECT_NE(said.find("could not write the level spectra cache"), std::string::npos) << said;
  EXPECT_GT(m.stiffness_spectrum.eigenvalue, 0.0);
  if (saved.empty())
    ::unsetenv("MRSIM_CACHE_DIR");
  else
    ::setenv("MRSIM_CACHE_DIR", saved.c_str(), 1);
}

// A folder keyed by the build would grow with every rebuild: past 512 results the oldest go.
TEST(ResultCache, PastTheLimitTheOldestResultsGo) {
  CacheFolder folder("spectra");
  const std::filesystem::path dir = result_cache_dir("spectra");
  aged_results(dir, "old_", ".json", 600, 2, 1000);
  const TetMesh mesh = box();
  cached_level_model(mesh, law(), false, held(mesh));
  const auto files = folder.files("spectra");
  EXPECT_EQ(files.size(), 384u);
  bool newest = false, oldest = false;
  for (const auto& f : files) {
    newest |= f.filename().string().rfind("level_spectra_", 0) == 0;
    oldest |= f.filename() == "old_0.json";
  }
  EXPECT_TRUE(newest) << "the result just written stays";
  EXPECT_FALSE(oldest);
  bool reused = false;
  cached_level_model(mesh, law(), false, held(mesh), &reused);
  EXPECT_TRUE(reused);
}

// Large binary results (the hierarchy's links) count by size too: past 256 MiB in a folder the
// oldest go, down to three quarters of it. Sparse files: their size costs no disk.
TEST(ResultCache, PastTheByteLimitTheOldestResultsGo) {
  CacheFolder folder("spectra");
  const std::filesystem::path dir = result_cache_dir("spectra");
  aged_results(dir, "big_", ".bin", 3, std::uintmax_t{100} << 20, 10);
  write_cached_bytes(dir / "small.bin", "0123456789abcdef", "payload", "test");
  EXPECT_EQ(folder.names("spectra"), (std::vector<std::string>{"big_2.bin", "small.bin"}));
  bool read = false;
  EXPECT_TRUE(read_cached_bytes(dir / "small.bin", "0123456789abcdef", "test",
                                [&](std::string_view p) { read = p == "payload"; }));
  EXPECT_TRUE(read);
}

// The result just written stays, even when it alone is over the limit; the older ones go.
TEST(ResultCache, TheResultJustWrittenStaysWhateverItsSize) {
  CacheFolder folder("spectra");
  const std::filesystem::path dir = result_cache_dir("spectra");
  aged_results(dir, "old_", ".bin", 3, 100, 10);
  const std::filesystem::path big = dir / "big.bin";
  std::ofstream(big) << std::string(2000, 'x');  // the newest, and alone above 1000 bytes
  prune_results(dir, big, {10, 1000});
  EXPECT_EQ(folder.names("spectra"), (std::vector<std::string>{"big.bin"}));
  // Without `kept`, it would go too.
  prune_results(dir, dir / "other.bin", {10, 1000});
  EXPECT_TRUE(folder.files("spectra").empty());
}
