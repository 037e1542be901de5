#include "meshing/simplified_surface_source.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>

#include "meshing/discrete_surface.hpp"
#include "meshing/gmsh_session.hpp"
#include "meshing/surface_improvement.hpp"
#include "meshing/surface_simplifier.hpp"

namespace mrsim {
namespace {

// Fewer boundary triangles than this cannot bound a useful solid (a tetrahedron has 4).
constexpr std::size_t kMinTriangles = 8;

}  // namespace

SimplifiedSurfaceSource::SimplifiedSurfaceSource(SurfaceMesh surface, double enclosed_volume, std::string name)
    : surface_(std::move(surface)), volume_(enclosed_volume), name_(std::move(name)) {
  for (int t = 0; t < static_cast<int>(surface_.triangles.size()); ++t) area_ += triangle_area(surface_, t);
}

std::size_t SimplifiedSurfaceSource::target_triangles(double size) const {
  const double equilateral_area = std::sqrt(3.0) / 4.0 * size * size;
  return std::max(kMinTriangles, static_cast<std::size_t>(std::lround(area_ / equilateral_area)));
}

SurfaceMesh SimplifiedSurfaceSource::simplified(double size) const {
  SimplifyOptions options;
  options.target_triangles = target_triangles(size);
  return improve_triangle_shapes(simplify_surface(surface_, options).surface);
}

void SimplifiedSurfaceSource::build(GmshModel& model, double size) const {
  const int surface_tag = add_discrete_surface(simplified(size));
  // A discrete surface without a parametrisation is not remeshed: its triangles are the
  // boundary of the volume as they are. (gmsh 4.8 does not fill a discrete volume, hence a
  // built-in-kernel volume bounded by the discrete surface.)
  const int loop = gmsh::model::geo::addSurfaceLoop({surface_tag});
  gmsh::model::geo::addVolume({loop});
  gmsh::model::geo::synchronize();
  model.throw_on_errors("cannot build a volume inside the simplified surface of " + name_);
}

}  // namespace mrsim
