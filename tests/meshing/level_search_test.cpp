// Live meshing on small targets: counts within the band, quality, volume, determinism, and
// the written files reload through mrsim's own mesh reader.
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "mesh/mesh_reader.hpp"
#include "meshing/level_outputs.hpp"
#include "meshing/level_set.hpp"
#include "meshing/shapes.hpp"
#include "meshing/surface_input.hpp"
#include "meshing_test_support.hpp"

namespace mrsim::test {
namespace {

std::string bytes_of(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void expect_good_level(const LevelRecord& r, double reference_volume) {
  const TetQuality& q = r.level.quality;
  const double target = static_cast<double>(r.requested_tets);
  EXPECT_TRUE(r.level.within_tolerance);
  EXPECT_NEAR(static_cast<double>(q.tets), target, 0.2 * target);
  EXPECT_GE(q.min_dihedral_deg, 10.0);
  EXPECT_NEAR(q.volume / reference_volume, 1.0, 0.02);
}

TEST(LevelSearch, SphereLevelsAreWithinBandGoodAndDeterministic) {
  ScratchDir dir;
  const auto sphere = make_shape_source(make_shape_spec("sphere", {0.05}));
  const auto levels = build_levels(*sphere, checked_targets({1200, 170}));
  ASSERT_EQ(levels.size(), 2u);
  EXPECT_EQ(levels[0].requested_tets, 170u);  // sorted coarse to fine
  for (const LevelRecord& r : levels) expect_good_level(r, sphere->volume());
  EXPECT_NEAR(sphere->volume(), 4.0 / 3.0 * 3.141592653589793 * 1.25e-4, 1e-9);

  const auto first = write_level_outputs(levels, {{"shape", "sphere"}}, sphere->name(), sphere->volume(), dir.file("a"));
  const auto again = build_levels(*sphere, {170, 1200});
  const auto second = write_level_outputs(again, {{"shape", "sphere"}}, sphere->name(), sphere->volume(), dir.file("b"));
  for (std::size_t k = 0; k < 2; ++k) EXPECT_EQ(bytes_of(first.meshes[k]), bytes_of(second.meshes[k])) << k;
  auto without_files = [](nlohmann::json j) {
    for (auto& level : j["levels"]) level.erase("file");
    return j;
  };
  EXPECT_EQ(without_files(nlohmann::json::parse(bytes_of(first.quality))),
            without_files(nlohmann::json::parse(bytes_of(second.quality))));

  // mrsim's reader takes the files back unchanged (all tets positive, no unused point).
  MeshReadReport report;
  const TetMesh loaded = read_tet_mesh(first.meshes[1], LengthUnit::Metre, &report);
  EXPECT_EQ(loaded.tets.size(), levels[1].level.quality.tets);
  EXPECT_EQ(loaded.points.size(), levels[1].level.quality.points);
  EXPECT_EQ(report.reoriented_tets, 0);

  const auto json = nlohmann::json::parse(bytes_of(first.quality));
  EXPECT_EQ(json["levels"].size(), 2u);
  EXPECT_EQ(json["levels"][0]["file"], "a_L0.vtu");
  EXPECT_EQ(json["resolution_ratios"].size(), 1u);
  EXPECT_EQ(json["levels"][1]["radius_ratio"]["histogram_counts"].size(), 10u);
  const std::string snippet = bytes_of(first.snippet);
  EXPECT_NE(snippet.find("    - mesh: a_L0.vtu"), std::string::npos) << snippet;
  EXPECT_NE(snippet.find("    - mesh: a_L1.vtu"), std::string::npos) << snippet;
}

TEST(LevelSearch, BeamIsAxisAlignedFromTheOrigin) {
  const auto beam = make_shape_source(make_shape_spec("beam", {}));
  EXPECT_NEAR(beam->volume(), 0.1 * 0.02 * 0.02, 1e-12);
  const auto levels = build_levels(*beam, {300});
  expect_good_level(levels[0], beam->volume());
  Vec3 lo = levels[0].level.mesh.points[0], hi = lo;
  for (const Vec3& p : levels[0].level.mesh.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  EXPECT_NEAR(lo.norm(), 0.0, 1e-12);
  EXPECT_NEAR((hi - Vec3(0.1, 0.02, 0.02)).norm(), 0.0, 1e-12);
}

TEST(LevelSearch, TinyTargetsGetAsCloseAsTheGeometryAllows) {
  const auto box = make_shape_source(make_shape_spec("box", {}));
  const auto levels = build_levels(*box, {30});
  EXPECT_GE(levels[0].level.quality.tets, 5u);
  EXPECT_LE(levels[0].level.quality.tets, 60u);
  EXPECT_GE(levels[0].level.quality.min_dihedral_deg, 10.0);
}

TEST(LevelSearch, ThesisLiverSizesLandInTheBand) {
  // The count is not monotone in the size at a few dozen tets: 28 asked of the bundled liver
  // gave 42 (+50 %) from the secant search alone; the scan around it lands in the band.
  const auto file = source_dir() / "scenarios" / "meshes" / "liver_surface_cgal_h10_mm.off";
  const SurfaceInput liver = load_surface_input(file, "mm", 1e-3, 180.0);
  for (const LevelRecord& r : build_levels(*liver.source, {28, 172})) {
    EXPECT_TRUE(r.level.within_tolerance) << r.requested_tets;
    EXPECT_NEAR(static_cast<double>(r.level.quality.tets), r.requested_tets, 0.2 * r.requested_tets);
  }
}

TEST(LevelSearch, LevelsThatComeOutIdenticalAreAnErrorNamingBoth) {
  // The box cannot be meshed with fewer than 24 tets: 8 and 20 would both be that mesh.
  const auto box = make_shape_source(make_shape_spec("box", {}));
  expect_input_error([&] { build_levels(*box, {8, 20}); },
                     {"L0 (asked 8)", "L1 (asked 20)", "same 24-tet mesh"});
}

TEST(LevelSearch, SharedSurfacesMesh) {
  MRSIM_REQUIRE_SHARED_DATA();
  for (const char* name : {"sphere.off", "ellipsoid.off"}) {
    const SurfaceInput in = load_surface_input(shared_data() / "cgal" / name, "m", 1.0, 180.0);
    const auto levels = build_levels(*in.source, {600});
    expect_good_level(levels[0], in.source->volume());
  }
}

TEST(ShapeSpecs, BadShapesAndDimensionsAreInputErrors) {
  expect_input_error([] { make_shape_spec("torus", {}); }, {"unknown shape 'torus'", "little_man"});
  expect_input_error([] { make_shape_spec("box", {1, 2}); }, {"box takes 3 dimension"});
  expect_input_error([] { make_shape_spec("sphere", {-1}); }, {"positive"});
  expect_input_error([] { checked_targets({}); }, {"--tets"});
  expect_input_error([] { checked_targets({3}); }, {"too few"});
  expect_input_error([] { checked_targets({30, 30}); }, {"different"});
}

}  // namespace
}  // namespace mrsim::test
