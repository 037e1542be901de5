// The committed levels of scenarios/meshes (made by scripts/make_bundled_meshes.sh): they
// load, their counts are within the band, min dihedral >= 10 deg, and the finer levels keep
// the object's volume within 2 %; and the quick ones still come out of the meshing code byte
// for byte, so a change to it cannot leave the committed files stale unnoticed.
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "mesh/mesh_reader.hpp"
#include "meshing/level_outputs.hpp"
#include "meshing/level_set.hpp"
#include "meshing/shapes.hpp"
#include "meshing/surface_input.hpp"
#include "meshing/tet_quality.hpp"
#include "meshing_test_support.hpp"

namespace mrsim::test {
namespace {

void check_bundled(const std::string& object, std::size_t level_count) {
  const auto dir = source_dir() / "scenarios" / "meshes";
  std::ifstream in(dir / (object + "_quality.json"));
  ASSERT_TRUE(in) << object;
  const auto report = nlohmann::json::parse(in);
  const double reference = report["reference_volume_m3"];
  ASSERT_EQ(report["levels"].size(), level_count);
  std::size_t previous = 0;
  for (std::size_t k = 0; k < level_count; ++k) {
    const auto& level = report["levels"][k];
    const auto file = dir / level["file"].get<std::string>();
    EXPECT_LT(std::filesystem::file_size(file), 2u << 20) << file;
    const TetQuality q = measure_quality(read_tet_mesh(file, LengthUnit::Metre));
    EXPECT_EQ(q.tets, level["tets"].get<std::size_t>()) << file;
    EXPECT_GT(q.tets, previous) << file;
    previous = q.tets;
    const double requested = level["requested_tets"];
    // Every level, the coarsest too (issue 19: the thesis' 28 tets once came out as 42).
    EXPECT_NEAR(static_cast<double>(q.tets), requested, 0.2 * requested) << file;
    EXPECT_GE(q.min_dihedral_deg, 10.0) << file;
    if (k + 2 >= level_count) {  // the two finest levels
      EXPECT_NEAR(q.volume / reference, 1.0, 0.02) << file;
    }
  }
}

std::string bytes_of(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Meshes `targets` of `source` (the first levels of `object`, as the script asks for them:
/// every level is searched independently) and compares the VTU files with the committed ones.
void expect_regenerated(const GeometrySource& source, const std::string& object, std::vector<std::size_t> targets) {
  ScratchDir dir;
  const auto levels = build_levels(source, targets);
  const auto out = write_level_outputs(levels, {}, source.name(), source.volume(), dir.file(object));
  const auto committed = source_dir() / "scenarios" / "meshes";
  for (std::size_t k = 0; k < out.meshes.size(); ++k) {
    const auto file = committed / out.meshes[k].filename();
    EXPECT_TRUE(bytes_of(out.meshes[k]) == bytes_of(file))
        << file << " differs from what mrsim mesh makes now: rerun scripts/make_bundled_meshes.sh and commit";
  }
}

TEST(BundledMeshes, QuickLevelsRegenerateByteForByte) {
  const auto liver_file = source_dir() / "scenarios" / "meshes" / "liver_surface_cgal_h10_mm.off";
  const SurfaceInput liver = load_surface_input(liver_file, "mm", 1e-3, 180.0);
  expect_regenerated(*liver.source, "liver", {30, 170});
  expect_regenerated(*liver.source, "liver_thesis", {28, 172});
  const auto beam = make_shape_source(make_shape_spec("beam", {0.1, 0.02, 0.02}));
  expect_regenerated(*beam, "beam", {30, 170, 1900});
}

TEST(BundledMeshes, Liver) { check_bundled("liver", 4); }
TEST(BundledMeshes, LiverThesis) { check_bundled("liver_thesis", 3); }
TEST(BundledMeshes, LittleMan) { check_bundled("little_man", 3); }
TEST(BundledMeshes, Beam) { check_bundled("beam", 3); }

}  // namespace
}  // namespace mrsim::test
