#include "cli/mesh_command.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/guarded_run.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "meshing/level_outputs.hpp"
#include "meshing/level_set.hpp"
#include "meshing/shapes.hpp"
#include "meshing/surface_input.hpp"

namespace mrsim {
namespace {

struct MeshArgs {
  std::string input;
  std::string shape;
  std::vector<double> dims;
  std::vector<std::size_t> tets;
  std::string prefix;
  std::string units = "m";
  double feature_angle = 180.0;
  bool quiet = false;
};

struct Source {
  std::unique_ptr<GeometrySource> geometry;
  nlohmann::ordered_json description;
};

Source make_source(const MeshArgs& a) {
  if (a.input.empty() == a.shape.empty()) {
    throw InputError("mrsim mesh: give either a surface file or --shape NAME (not both)");
  }
  if (!a.dims.empty() && a.shape.empty()) throw InputError("mrsim mesh: --dims goes with --shape");
  const double metres_per_unit = a.units == "mm" ? 1e-3 : 1.0;
  if (!a.input.empty()) {
    SurfaceInput in = load_surface_input(a.input, a.units, metres_per_unit, a.feature_angle);
    return {std::move(in.source), std::move(in.description)};
  }
  std::vector<double> dims = a.dims;
  for (double& d : dims) d *= metres_per_unit;
  const ShapeSpec spec = make_shape_spec(a.shape, dims);
  auto geometry = make_shape_source(spec);
  nlohmann::ordered_json description{{"shape", spec.kind}, {"dims_m", spec.dims}, {"enclosed_volume_m3", geometry->volume()}};
  return {std::move(geometry), std::move(description)};
}

void check_prefix(const std::filesystem::path& prefix) {
  if (prefix.filename().empty()) throw InputError("-o: give a file prefix such as out/liver, not a folder");
  const std::filesystem::path folder = prefix.parent_path();
  std::error_code ec;
  if (!folder.empty() && !std::filesystem::is_directory(folder, ec)) {
    throw InputError("-o: folder " + folder.string() + " does not exist");
  }
}

void print_level(const LevelRecord& r, std::size_t k) {
  const TetQuality& q = r.level.quality;
  char line[256];
  std::snprintf(line, sizeof line, "L%zu: %zu tets (asked %zu%s), %zu points, dihedral %.1f..%.1f deg, "
                "mean radius ratio %.3f%s, %.1f s", k, q.tets, r.requested_tets,
                r.level.within_tolerance ? "" : ", outside +-20%", q.points, q.min_dihedral_deg,
                q.max_dihedral_deg, q.mean_radius_ratio,
                r.level.simplified_surface ? ", simplified surface (gmsh could not remesh it)" : "", r.seconds);
  info(line);
  if (!r.level.within_tolerance)
    warn("L" + std::to_string(k) + ": no mesh within +-20% of " + std::to_string(r.requested_tets) +
         " tets was found (" + std::to_string(r.level.candidates) + " sizes tried); the closest, " +
         std::to_string(q.tets) + " tets, is kept");
}

int run_mesh(const MeshArgs& a) {
  set_quiet(a.quiet);
  const std::vector<std::size_t> targets = checked_targets(a.tets);
  check_prefix(a.prefix);
  const Source source = make_source(a);
  std::size_t k = 0;
  const auto levels = build_levels(*source.geometry, targets, [&k](const LevelRecord& r) { print_level(r, k++); });
  const LevelOutputs out = write_level_outputs(levels, source.description, source.geometry->name(),
                                               source.geometry->volume(), a.prefix);
  info("mrsim mesh: wrote " + std::to_string(out.meshes.size()) + " levels, " + out.quality.string() + " and " +
       out.snippet.string());
  return kExitOk;
}

void add_mesh_options(CLI::App* cmd, MeshArgs& args) {
  cmd->add_option("input", args.input, "Closed triangulated surface: .stl, .obj, .off or .ply");
  std::string shapes;
  for (const auto& name : shape_names()) shapes += (shapes.empty() ? "" : "|") + name;
  cmd->add_option("--shape", args.shape, "Built-in solid instead of a file: " + shapes);
  cmd->add_option("--dims", args.dims, "Dimensions of --shape, comma-separated, in --units (see docs/meshing.md)")
      ->delimiter(',');
  cmd->add_option("--tets", args.tets, "Tet count of each level, comma-separated, e.g. 30,170,1900")
      ->delimiter(',')->required();
  cmd->add_option("-o,--output", args.prefix, "Output prefix: writes PREFIX_L0.vtu..., PREFIX_quality.json, "
                  "PREFIX_levels.yaml")->required();
  cmd->add_option("--units", args.units, "Units of the input file and of --dims (outputs are in metres)")
      ->check(CLI::IsMember({"m", "mm"}));
  cmd->add_option("--feature-angle", args.feature_angle,
                  "Surface edges sharper than this (degrees) are kept as creases; 180: smooth surface")
      ->check(CLI::Range(1.0, 180.0));
  cmd->add_flag("-q,--quiet", args.quiet, "No progress on stderr");
}

}  // namespace

int run_mesh_cli(int argc, char** argv) {
  CLI::App app{kMeshDescription, "mrsim mesh"};
  MeshArgs args;
  add_mesh_options(&app, args);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  return guarded_run([&args] { return run_mesh(args); });
}

}  // namespace mrsim
