#include "meshing/volume_mesher.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cstdlib>
#include <unordered_map>

#include "meshing/gmsh_session.hpp"

namespace mrsim {
namespace {

constexpr int kTetrahedron = 4;  // gmsh element type of a 4-node tetrahedron
constexpr unsigned kRandomSeed = 1;

void set_options(const MeshSettings& s) {
  namespace opt = gmsh::option;
  // Determinism: one thread everywhere and a fixed seed for the random perturbations.
  opt::setNumber("General.NumThreads", 1);
  opt::setNumber("Mesh.MaxNumThreads1D", 1);
  opt::setNumber("Mesh.MaxNumThreads2D", 1);
  opt::setNumber("Mesh.MaxNumThreads3D", 1);
  opt::setNumber("Mesh.RandomSeed", kRandomSeed);
  // A uniform size: the hierarchy wants every level as regular as possible.
  opt::setNumber("Mesh.MeshSizeMin", s.size);
  opt::setNumber("Mesh.MeshSizeMax", s.size);
  opt::setNumber("Mesh.MeshSizeFactor", 1.0);
  opt::setNumber("Mesh.MeshSizeFromCurvature", 0);
  opt::setNumber("Mesh.MeshSizeFromPoints", 0);
  opt::setNumber("Mesh.MeshSizeExtendFromBoundary", 1);
  opt::setNumber("Mesh.ElementOrder", 1);
  const bool hxt = s.algorithm == MeshAlgorithm::Hxt;
  opt::setNumber("Mesh.Algorithm", hxt ? 6 : 5);
  opt::setNumber("Mesh.Algorithm3D", hxt ? 10 : 1);
  // gmsh's own tet optimiser (Netgen's is not in Debian's build) on every tet whose quality
  // is below the threshold.
  opt::setNumber("Mesh.Optimize", 1);
  opt::setNumber("Mesh.OptimizeThreshold", hxt ? 0.3 : 0.5);
}

TetMesh extract_tets() {
  std::vector<std::size_t> tet_tags, corners;
  gmsh::model::mesh::getElementsByType(kTetrahedron, tet_tags, corners);
  std::vector<std::size_t> node_tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, true, false);
  // Only the nodes tets use (gmsh keeps unused nodes of the input surface), in node-tag order.
  std::vector<std::size_t> used(corners);
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::unordered_map<std::size_t, int> index_of;
  for (std::size_t i = 0; i < used.size(); ++i) index_of[used[i]] = static_cast<int>(i);
  TetMesh mesh;
  mesh.points.resize(used.size());
  for (std::size_t i = 0; i < node_tags.size(); ++i) {
    const auto it = index_of.find(node_tags[i]);
    if (it != index_of.end()) mesh.points[it->second] = Vec3(coords[3 * i], coords[3 * i + 1], coords[3 * i + 2]);
  }
  mesh.tets.resize(tet_tags.size());
  for (std::size_t t = 0; t < tet_tags.size(); ++t) {
    Tet& tet = mesh.tets[t];
    for (int c = 0; c < 4; ++c) tet[c] = index_of.at(corners[4 * t + c]);
    const auto& p = mesh.points;
    if (signed_volume(p[tet[0]], p[tet[1]], p[tet[2]], p[tet[3]]) < 0.0) std::swap(tet[2], tet[3]);
  }
  return mesh;
}

}  // namespace

std::string algorithm_name(MeshAlgorithm algorithm) {
  return algorithm == MeshAlgorithm::Hxt ? "frontal-delaunay+hxt" : "delaunay+delaunay";
}

TetMesh mesh_solid(const GeometrySource& source, const MeshSettings& settings) {
  GmshModel model("mrsim_mesh");
  set_options(settings);
  model.throw_on_errors("gmsh options");
  {
    // Parts of gmsh draw from the C library's rand() (point perturbations) and seed it only
    // at initialisation: reseeding here makes an attempt independent of those before it.
    std::srand(kRandomSeed);
    const SilencedOutput quiet;
    source.build(model, settings.size);
    gmsh::model::mesh::generate(3);
  }
  model.throw_on_errors("gmsh could not mesh " + source.name());
  TetMesh mesh = extract_tets();
  if (mesh.tets.empty()) throw GmshFailure("gmsh produced no tetrahedron for " + source.name());
  return mesh;
}

}  // namespace mrsim
