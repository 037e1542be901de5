#include "io/hdf5_level_group.hpp"

#include <vector>

#include "io/hdf5_attributes.hpp"
#include "io/hdf5_group.hpp"
#include "io/hdf5_static_dataset.hpp"

namespace mrsim::h5 {
namespace {

void write_rest_positions(hid_t group, const std::string& path, const TetMesh& mesh,
                          const std::string& file) {
  std::vector<double> xyz;
  xyz.reserve(3 * mesh.points.size());
  for (const Vec3& p : mesh.points) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  const std::string object = path + "/rest_positions";
  write_static_dataset<double>(group, "rest_positions", xyz, {mesh.points.size(), 3}, "m",
                               {file, object});
}

void write_tets(hid_t group, const std::string& path, const TetMesh& mesh,
                const std::string& file) {
  std::vector<std::int32_t> ids;
  ids.reserve(4 * mesh.tets.size());
  for (const Tet& t : mesh.tets) ids.insert(ids.end(), t.begin(), t.end());
  const std::string object = path + "/tets";
  write_static_dataset<std::int32_t>(group, "tets", ids, {mesh.tets.size(), 4}, "",
                                     {file, object});
}

ExtendibleSpec status_spec(std::size_t points) {
  ExtendibleSpec spec;
  spec.name = "status";
  spec.file_type = TypeOf<std::int8_t>::file();
  spec.row_shape = {points};
  // One row per chunk, each written once and never rewritten. A compressed chunk of several
  // frames changes size as it fills and HDF5 moves it: a run killed during that move lost
  // frames already complete ("inflate() failed"), which a resumed run must cut back to
  // (py.test_resume found it, 1 run in 4, with up to 16 rows per chunk).
  spec.chunk_rows = 1;
  // Long runs of equal status compress very well, but zlib's set-up (some 100 000 instructions,
  // its tables cleared) is paid per chunk, so per row: on liver_probe's three coarse levels
  // (20 to 544 points) that was most of each frame's log writing. Rows of a few hundred bytes
  // stay as they are; from 1024 points they are deflated.
  spec.deflate_level = points >= 1024 ? 4 : 0;
  spec.deflate_runs = true;  // liver_L3's rows: 14.0 kB deflated, 16.0 kB at the default
  spec.description = "per frame and point: 0 inactive, 1 ghost, 2 active";
  return spec;
}

}  // namespace

LevelGroup::LevelGroup(hid_t levels_group, int level, const TetMesh& mesh, const std::string& file)
    : path_("/levels/level_" + std::to_string(level)), file_(file), points_(mesh.points.size()) {
  bool created = true;
  group_ = open_or_create_group(levels_group, "level_" + std::to_string(level), {file_, path_},
                                created);
  if (created) {
    write_rest_positions(group_.get(), path_, mesh, file_);
    write_tets(group_.get(), path_, mesh, file_);
  }
  status_ = ExtendibleDataset(group_.get(), path_, status_spec(points_), file_,
                              created ? ExtendibleDataset::Mode::Create
                                      : ExtendibleDataset::Mode::Reopen);
}

void LevelGroup::set_attribute(const std::string& name, std::span<const double> values) {
  set_double_array_attribute(group_.get(), name.c_str(), values, {file_, path_});
}

void LevelGroup::close() {
  status_.close();
  check(group_.close(), {file_, path_}, "close group");
}

}  // namespace mrsim::h5
