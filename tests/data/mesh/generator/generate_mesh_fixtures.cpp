// Writes the mesh-reader fixtures of tests/data/mesh/: one small box mesh in every input format
// mrsim reads. The gmsh and Medit files are written by gmsh's own writer and the .vtu files by
// VTK's, so the tests read real outputs of those tools, not our idea of them. TetGen has no
// library writer here, so its files are written by hand following TetGen's manual.
//
// Usage: generate_mesh_fixtures OUTPUT_DIR   (see ../README.md)
#include <gmsh.h>
#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "mesh/box_mesh.hpp"

namespace {

using mrsim::TetMesh;
using mrsim::Vec3;
using Tri = std::array<int, 3>;

struct Fixture {
  TetMesh mesh;             // boundary vertices first, then interior ones
  std::vector<Tri> skin;    // boundary triangles, written as 2-D cells that readers ignore
  std::size_t boundary_count = 0;
};

// Six significant digits: every writer (even %.16g or VTK's ascii) prints these doubles in a
// form that parses back to the same bits, so all fixtures hold exactly the same points.
double round6(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return std::strtod(buf, nullptr);
}

bool on_box_boundary(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  for (int a = 0; a < 3; ++a)
    if (p[a] == lo[a] || p[a] == hi[a]) return true;
  return false;
}

Fixture make_fixture() {
  const Vec3 lo(round6(-0.05), round6(0.01), round6(0.02));
  const Vec3 hi(round6(0.07), round6(0.13), round6(0.10));
  TetMesh box = mrsim::make_box_mesh(lo, hi, 3, 2, 2);
  for (Vec3& p : box.points)
    for (int a = 0; a < 3; ++a) p[a] = round6(p[a]);

  // Boundary vertices first so that gmsh, which writes node blocks surface-then-volume, keeps
  // the same vertex order as the other formats.
  std::vector<int> order(box.points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_partition(order.begin(), order.end(),
                        [&](int i) { return on_box_boundary(box.points[i], lo, hi); });
  std::vector<int> new_id(order.size());
  Fixture f;
  for (std::size_t k = 0; k < order.size(); ++k) {
    new_id[order[k]] = static_cast<int>(k);
    f.mesh.points.push_back(box.points[order[k]]);
    if (on_box_boundary(box.points[order[k]], lo, hi)) ++f.boundary_count;
  }
  for (const auto& t : box.tets) f.mesh.tets.push_back({new_id[t[0]], new_id[t[1]], new_id[t[2]], new_id[t[3]]});

  // Boundary faces are the tet faces that occur once.
  std::map<std::array<int, 3>, std::pair<int, Tri>> faces;
  for (const auto& t : f.mesh.tets)
    for (int skip = 0; skip < 4; ++skip) {
      Tri tri{};
      int n = 0;
      for (int c = 0; c < 4; ++c)
        if (c != skip) tri[n++] = t[c];
      std::array<int, 3> key = tri;
      std::sort(key.begin(), key.end());
      auto& e = faces[key];
      e.first += 1;
      e.second = tri;
    }
  for (const auto& [key, e] : faces)
    if (e.first == 1) f.skin.push_back(e.second);
  return f;
}

// Non-contiguous node tags exercise the tag -> index map of the gmsh reader.
std::size_t node_tag(int index) { return 10 + 3 * static_cast<std::size_t>(index); }

void build_gmsh_model(const Fixture& f) {
  gmsh::model::add("box");
  gmsh::model::addDiscreteEntity(2, 1);
  gmsh::model::addDiscreteEntity(3, 1, {1});
  std::vector<std::size_t> surf_tags, vol_tags;
  std::vector<double> surf_xyz, vol_xyz;
  for (std::size_t i = 0; i < f.mesh.points.size(); ++i) {
    const bool boundary = i < f.boundary_count;
    (boundary ? surf_tags : vol_tags).push_back(node_tag(static_cast<int>(i)));
    for (int a = 0; a < 3; ++a) (boundary ? surf_xyz : vol_xyz).push_back(f.mesh.points[i][a]);
  }
  gmsh::model::mesh::addNodes(2, 1, surf_tags, surf_xyz);
  gmsh::model::mesh::addNodes(3, 1, vol_tags, vol_xyz);

  std::vector<std::size_t> tri_ids, tri_nodes, tet_ids, tet_nodes;
  std::size_t next_id = 1;
  for (const auto& t : f.skin) {
    tri_ids.push_back(next_id++);
    for (int v : t) tri_nodes.push_back(node_tag(v));
  }
  for (const auto& t : f.mesh.tets) {
    tet_ids.push_back(next_id++);
    for (int v : t) tet_nodes.push_back(node_tag(v));
  }
  gmsh::model::mesh::addElementsByType(1, 2, tri_ids, tri_nodes);
  gmsh::model::mesh::addElementsByType(1, 4, tet_ids, tet_nodes);
  gmsh::model::addPhysicalGroup(2, {1}, 2);
  gmsh::model::addPhysicalGroup(3, {1}, 1);
}

void write_gmsh(const std::filesystem::path& dir) {
  struct Variant {
    const char* name;
    double version;
    int binary;
  };
  for (const Variant& v : {Variant{"box_msh22_ascii.msh", 2.2, 0}, Variant{"box_msh22_binary.msh", 2.2, 1},
                           Variant{"box_msh41_ascii.msh", 4.1, 0}, Variant{"box_msh41_binary.msh", 4.1, 1}}) {
    gmsh::option::setNumber("Mesh.MshFileVersion", v.version);
    gmsh::option::setNumber("Mesh.Binary", v.binary);
    gmsh::write((dir / v.name).string());
  }
  gmsh::option::setNumber("Mesh.Binary", 0);
  gmsh::write((dir / "box_medit.mesh").string());
}

void write_vtu(const Fixture& f, const std::filesystem::path& dir) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const Vec3& p : f.mesh.points) points->InsertNextPoint(p.x(), p.y(), p.z());
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  for (const auto& t : f.skin) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    grid->InsertNextCell(VTK_TRIANGLE, 3, ids);
  }
  for (const auto& t : f.mesh.tets) {
    const vtkIdType ids[4] = {t[0], t[1], t[2], t[3]};
    grid->InsertNextCell(VTK_TETRA, 4, ids);
  }
  struct Variant {
    const char* name;
    int mode;
    bool compress;
    bool base64;      // appended data: base64 text instead of raw bytes
    bool big_endian;  // as written on a big-endian machine
  };
  for (const Variant& v : {Variant{"box_appended_zlib.vtu", vtkXMLWriter::Appended, true, false, false},
                           Variant{"box_appended_zlib_bigendian.vtu", vtkXMLWriter::Appended, true, false, true},
                           Variant{"box_appended_base64.vtu", vtkXMLWriter::Appended, false, true, false},
                           Variant{"box_inline_zlib.vtu", vtkXMLWriter::Binary, true, false, false},
                           Variant{"box_ascii.vtu", vtkXMLWriter::Ascii, false, false, false}}) {
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetInputData(grid);
    writer->SetFileName((dir / v.name).string().c_str());
    writer->SetDataMode(v.mode);
    writer->SetEncodeAppendedData(v.base64);
    if (v.big_endian)
      writer->SetByteOrderToBigEndian();
    else
      writer->SetByteOrderToLittleEndian();
    if (v.compress)
      writer->SetCompressorTypeToZLib();
    else
      writer->SetCompressorTypeToNone();
    if (writer->Write() != 1) {
      std::fprintf(stderr, "VTK could not write %s\n", v.name);
      std::exit(1);
    }
  }
}

// TetGen: '#' comments, one point attribute and boundary markers in the 0-based files; a
// region attribute on the tets in the 1-based ones.
void write_tetgen(const Fixture& f, const std::filesystem::path& dir, int base) {
  const std::string stem = (dir / ("box_tetgen_base" + std::to_string(base))).string();
  std::ofstream node(stem + ".node");
  node.precision(17);
  node << "# box fixture for mrsim, " << base << "-based\n";
  node << f.mesh.points.size() << "  3  " << (base == 0 ? "1  1" : "0  0") << '\n';
  for (std::size_t i = 0; i < f.mesh.points.size(); ++i) {
    const Vec3& p = f.mesh.points[i];
    node << "  " << i + base << "  " << p.x() << "  " << p.y() << "  " << p.z();
    if (base == 0) node << "  " << 0.5 * static_cast<double>(i) << "  " << (i < f.boundary_count ? 1 : 0);
    node << '\n';
  }
  node << "# generated by generate_mesh_fixtures\n";
  std::ofstream ele(stem + ".ele");
  ele << "# tetrahedra\n" << f.mesh.tets.size() << "  4  " << (base == 1 ? 1 : 0) << '\n';
  for (std::size_t i = 0; i < f.mesh.tets.size(); ++i) {
    const auto& t = f.mesh.tets[i];
    ele << "  " << i + base;
    for (int v : t) ele << "  " << v + base;
    if (base == 1) ele << "  7";
    ele << '\n';
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUTPUT_DIR\n", argv[0]);
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  const Fixture f = make_fixture();
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 1);
  build_gmsh_model(f);
  write_gmsh(dir);
  gmsh::finalize();
  write_vtu(f, dir);
  write_tetgen(f, dir, 0);
  write_tetgen(f, dir, 1);
  std::printf("%zu points (%zu on the boundary), %zu tets, %zu boundary triangles\n",
              f.mesh.points.size(), f.boundary_count, f.mesh.tets.size(), f.skin.size());
  return 0;
}
