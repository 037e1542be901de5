// load_scenario end to end: good files, typed fields, resolved YAML round trip, file errors.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include "scenario/scenario.hpp"
#include "scenario/schema_validator.hpp"
#include "test_support.hpp"

namespace mrsim {
namespace {

namespace fs = std::filesystem;

void expect_same(const Scenario& a, const Scenario& b) {
  EXPECT_EQ(a.name, b.name);
  ASSERT_EQ(a.levels.size(), b.levels.size());
  for (std::size_t i = 0; i < a.levels.size(); ++i) EXPECT_EQ(a.levels[i].mesh, b.levels[i].mesh);
  EXPECT_EQ(a.units, b.units);
  EXPECT_EQ(a.material.model, b.material.model);
  EXPECT_EQ(a.material.lambda, b.material.lambda);
  EXPECT_EQ(a.material.mu, b.material.mu);
  EXPECT_EQ(a.material.youngs_modulus, b.material.youngs_modulus);
  EXPECT_EQ(a.material.poisson, b.material.poisson);
  EXPECT_EQ(a.material.density, b.material.density);
  EXPECT_EQ(a.material.phi, b.material.phi);
  EXPECT_EQ(a.material.psi, b.material.psi);
  ASSERT_EQ(a.fixed.size(), b.fixed.size());
  for (std::size_t i = 0; i < a.fixed.size(); ++i) {
    EXPECT_EQ(a.fixed[i].kind, b.fixed[i].kind);
    EXPECT_EQ(a.fixed[i].min, b.fixed[i].min);
    EXPECT_EQ(a.fixed[i].max, b.fixed[i].max);
    EXPECT_EQ(a.fixed[i].point, b.fixed[i].point);
    EXPECT_EQ(a.fixed[i].normal, b.fixed[i].normal);
    EXPECT_EQ(a.fixed[i].ids, b.fixed[i].ids);
    EXPECT_EQ(a.fixed[i].level, b.fixed[i].level);
  }
  EXPECT_EQ(a.gravity, b.gravity);
  EXPECT_EQ(a.initial.velocity, b.initial.velocity);
  EXPECT_EQ(a.initial.angular_velocity, b.initial.angular_velocity);
  EXPECT_EQ(a.time.integrator, b.time.integrator);
  EXPECT_EQ(a.time.frame_dt, b.time.frame_dt);
  EXPECT_EQ(a.time.substeps, b.time.substeps);
  EXPECT_EQ(a.time.duration, b.time.duration);
  EXPECT_EQ(a.time.divergence_energy_factor, b.time.divergence_energy_factor);
  EXPECT_EQ(a.output.dir, b.output.dir);
  EXPECT_EQ(a.output.every, b.output.every);
  EXPECT_EQ(a.output.vtk, b.output.vtk);
  EXPECT_EQ(a.resolved, b.resolved);
}

TEST(ScenarioLoader, MinimalScenarioGetsEveryDefault) {
  const auto file = test::good_scenario("minimal.yaml");
  const Scenario s = load_scenario(file);
  EXPECT_EQ(s.name, "minimal");
  EXPECT_EQ(s.source, file);
  ASSERT_EQ(s.levels.size(), 1u);
  EXPECT_TRUE(s.levels[0].mesh.is_absolute());
  EXPECT_EQ(s.levels[0].mesh, file.parent_path() / "meshes/cube.vtu");
  EXPECT_EQ(s.units, LengthUnit::Metre);
  EXPECT_EQ(s.material.model, StrainModel::GreenLagrange);
  EXPECT_EQ(s.material.lambda, 5.0e4);
  EXPECT_EQ(s.material.mu, 1.0e4);
  EXPECT_DOUBLE_EQ(s.material.youngs_modulus, 1.0e4 * 17.0e4 / 6.0e4);
  EXPECT_DOUBLE_EQ(s.material.poisson, 5.0 / 12.0);
  EXPECT_EQ(s.material.density, 1000.0);
  EXPECT_EQ(s.material.phi, 0.0);
  EXPECT_EQ(s.material.psi, 0.0);
  EXPECT_TRUE(s.fixed.empty());
  EXPECT_EQ(s.gravity, Vec3(0, 0, -9.81));
  EXPECT_EQ(s.initial.velocity, Vec3::Zero());
  EXPECT_EQ(s.time.integrator, IntegratorKind::ModifiedEuler);
  EXPECT_EQ(s.time.frame_dt, 0.04);
  EXPECT_EQ(s.time.substeps, 0);  // computed from the meshes by the run
  EXPECT_EQ(s.time.courant, 1.0);
  EXPECT_TRUE(s.time.adapt_substeps);
  EXPECT_EQ(s.time.duration, 1.0);
  EXPECT_EQ(s.time.divergence_energy_factor, 1.0);
  EXPECT_EQ(s.output.dir, "out/minimal");
  EXPECT_EQ(s.output.every, 1);
  EXPECT_TRUE(s.output.vtk);
}

TEST(ScenarioLoader, FullScenarioFillsEveryField) {
  const auto file = test::good_scenario("full.yaml");
  const Scenario s = load_scenario(file);
  EXPECT_EQ(s.name, "full_cantilever");
  EXPECT_EQ(s.levels.at(0).mesh, (file.parent_path() / "../meshes/beam_L0.vtu").lexically_normal());
  EXPECT_EQ(s.units, LengthUnit::Millimetre);
  EXPECT_EQ(s.material.model, StrainModel::Cauchy);
  EXPECT_EQ(s.material.youngs_modulus, 1.0e5);
  EXPECT_EQ(s.material.poisson, 0.3);
  EXPECT_DOUBLE_EQ(s.material.lambda, 1.0e5 * 0.3 / (1.3 * 0.4));
  EXPECT_DOUBLE_EQ(s.material.mu, 1.0e5 / 2.6);
  EXPECT_EQ(s.material.density, 1100.0);
  EXPECT_EQ(s.material.phi, 0.5);
  EXPECT_EQ(s.material.psi, 20.0);
  ASSERT_EQ(s.fixed.size(), 3u);
  EXPECT_EQ(s.fixed[0].kind, FixedRegion::Kind::Box);
  EXPECT_EQ(s.fixed[0].min, Vec3(-1, -1, -1));
  EXPECT_EQ(s.fixed[0].max, Vec3(1, 1, -0.05));
  EXPECT_EQ(s.fixed[0].level, -1);
  EXPECT_EQ(s.fixed[1].kind, FixedRegion::Kind::HalfSpace);
  EXPECT_EQ(s.fixed[1].point, Vec3(0, 0, 0.1));
  EXPECT_EQ(s.fixed[1].normal, Vec3(0, 0, 1));
  EXPECT_EQ(s.fixed[2].kind, FixedRegion::Kind::Ids);
  EXPECT_EQ(s.fixed[2].ids, (std::vector<int>{0, 3, 7}));
  EXPECT_EQ(s.fixed[2].level, 0);
  EXPECT_EQ(s.gravity, Vec3(0, -9.81, 0));
  EXPECT_EQ(s.initial.velocity, Vec3(0.1, 0, 0));
  EXPECT_EQ(s.initial.angular_velocity, Vec3(0, 0, 0.5));
  EXPECT_EQ(s.time.integrator, IntegratorKind::StoermerVerlet);
  EXPECT_EQ(s.time.frame_dt, 0.02);
  EXPECT_EQ(s.time.substeps, 128);
  EXPECT_EQ(s.time.duration, 2.0);
  EXPECT_EQ(s.time.divergence_energy_factor, 10.0);
  EXPECT_EQ(s.output.dir, "results/full");
  EXPECT_EQ(s.output.every, 5);
  EXPECT_FALSE(s.output.vtk);
}

TEST(ScenarioLoader, ResolvedDocumentKeepsWhatTheUserWroteAndLogsBothPairs) {
  const Scenario s = load_scenario(test::good_scenario("full.yaml"));
  const auto& r = s.resolved;
  EXPECT_EQ(r["object"]["levels"][0]["mesh"], "../meshes/beam_L0.vtu");
  EXPECT_EQ(r["material"]["youngs_modulus"], 1.0e5);
  EXPECT_FALSE(r["material"].contains("lambda"));
  EXPECT_DOUBLE_EQ(r["material"]["derived"]["lambda"].get<double>(), s.material.lambda);
  EXPECT_DOUBLE_EQ(r["material"]["derived"]["mu"].get<double>(), s.material.mu);
  EXPECT_EQ(r["material"]["derived"]["youngs_modulus"], 1.0e5);
  EXPECT_EQ(r["material"]["derived"]["poisson_ratio"], 0.3);
  EXPECT_TRUE(scenario::schema_issues(r).empty());
}

TEST(ScenarioLoader, ResolvedYamlReloadsToTheSameScenario) {
  for (const char* name : {"minimal.yaml", "full.yaml"}) {
    SCOPED_TRACE(name);
    const auto file = test::good_scenario(name);
    const Scenario first = load_scenario(file);
    const std::string yaml = resolved_yaml(first);
    EXPECT_EQ(yaml.find("name: "), yaml.find('\n', yaml.rfind("# ", yaml.find("name: "))) + 1)
        << "name should be the first key:\n"
        << yaml;
    const Scenario again = load_scenario_text(yaml, file);
    expect_same(first, again);
    EXPECT_EQ(resolved_yaml(again), yaml);  // a fixed point
  }
}

TEST(ScenarioLoader, ResolvedYamlWrittenToAFileReloads) {
  test::TempDir dir;
  const Scenario first =
      load_scenario(test::good_scenario("full.yaml"), {"object.levels.0.mesh=/data/beam.vtu"});
  const auto file = dir.write("scenario.yaml", resolved_yaml(first));
  Scenario again = load_scenario(file);
  again.source = first.source;
  expect_same(first, again);
}

TEST(ScenarioLoader, ResolvedYamlUsesFloatsPyYamlReads) {
  const std::string yaml = resolved_yaml(load_scenario(test::good_scenario("full.yaml")));
  EXPECT_NE(yaml.find("youngs_modulus: 1.0e+5"), std::string::npos) << yaml;
  EXPECT_EQ(yaml.find("e5"), std::string::npos) << yaml;
}

TEST(ScenarioLoader, MissingUnreadableAndDirectoryFilesAreInputErrors) {
  test::TempDir dir;
  EXPECT_INPUT_ERROR(load_scenario(dir.path() / "nope.yaml"), "nope.yaml: no such file");
  EXPECT_INPUT_ERROR(load_scenario(dir.path()), "is a directory");
  const auto locked = dir.write("locked.yaml", "name: x\n");
  fs::permissions(locked, fs::perms::none);
  if (::geteuid() != 0)  // root reads anything
    EXPECT_INPUT_ERROR(load_scenario(locked), "locked.yaml: cannot be opened for reading");
  fs::permissions(locked, fs::perms::owner_all);
}

TEST(ScenarioLoader, ErrorsNameTheFileAsGiven) {
  test::TempDir dir;
  const auto file = dir.write("x.yaml",
                              "name: x\nobject:\n  levels:\n    - mesh: a.vtu\nmaterial:\n"
                              "  mu: 1\n  lambda: -5\n");
  EXPECT_INPUT_ERROR(load_scenario(file),
                     file.string() + ":7:3: material.lambda: must be >= 0 (got -5)");
}

TEST(ScenarioLoader, SchemaPathPointsToTheSourceSchema) {
  EXPECT_TRUE(fs::exists(schema_path())) << schema_path();
  EXPECT_EQ(schema_path().filename(), "scenario.schema.json");
}

}  // namespace
}  // namespace mrsim
