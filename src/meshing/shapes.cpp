#include "meshing/shapes.hpp"

#include <gmsh.h>

#include <cmath>
#include <map>
#include <sstream>

#include "core/error.hpp"
#include "meshing/gmsh_session.hpp"

namespace mrsim {
namespace {

struct ShapeInfo {
  std::size_t dim_count;
  std::vector<double> defaults;
  const char* dims_help;
};

const std::map<std::string, ShapeInfo>& shape_table() {
  static const std::map<std::string, ShapeInfo> table{
      {"box", {3, {0.1, 0.1, 0.1}, "a,b,c (edge lengths)"}},
      {"sphere", {1, {0.05}, "r (radius)"}},
      {"ellipsoid", {3, {0.05, 0.03, 0.02}, "a,b,c (semi-axes)"}},
      {"cylinder", {2, {0.02, 0.1}, "r,h (radius, height)"}},
      {"beam", {3, {0.1, 0.02, 0.02}, "L,W,H (length along x, width, height)"}},
      {"little_man", {1, {0.2}, "s (overall size)"}},
  };
  return table;
}

int build_little_man(double s) {
  namespace occ = gmsh::model::occ;
  // Proportions chosen so that the parts overlap generously: shallow overlaps would leave
  // thin wedges at the junctions, and thin wedges make poor tetrahedra.
  const int belly = occ::addSphere(0, 0, 0.3 * s, 0.3 * s);
  const int head = occ::addSphere(0, 0, 0.72 * s, 0.18 * s);
  const double arm_radius = 0.1 * s, arm_height = 0.36 * s;
  const int left = occ::addCylinder(0, 0, arm_height, -0.55 * s, 0, 0, arm_radius);
  const int right = occ::addCylinder(0, 0, arm_height, 0.55 * s, 0, 0, arm_radius);
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> map;
  occ::fuse({{3, belly}}, {{3, head}, {3, left}, {3, right}}, out, map);
  return out.size() == 1 ? out.front().second : -1;
}

int build_shape(const ShapeSpec& spec) {
  namespace occ = gmsh::model::occ;
  const auto& d = spec.dims;
  if (spec.kind == "box") return occ::addBox(-d[0] / 2, -d[1] / 2, -d[2] / 2, d[0], d[1], d[2]);
  if (spec.kind == "beam") return occ::addBox(0, 0, 0, d[0], d[1], d[2]);
  if (spec.kind == "sphere") return occ::addSphere(0, 0, 0, d[0]);
  if (spec.kind == "cylinder") return occ::addCylinder(0, 0, -d[1] / 2, 0, 0, d[1], d[0]);
  if (spec.kind == "ellipsoid") {
    const int tag = occ::addSphere(0, 0, 0, 1.0);
    occ::dilate({{3, tag}}, 0, 0, 0, d[0], d[1], d[2]);
    return tag;
  }
  return build_little_man(d[0]);
}

std::string describe(const ShapeSpec& spec) {
  std::ostringstream text;
  text << "shape " << spec.kind << '(';
  for (std::size_t i = 0; i < spec.dims.size(); ++i) text << (i ? "," : "") << spec.dims[i];
  text << " m)";
  return text.str();
}

class ShapeSource : public GeometrySource {
 public:
  explicit ShapeSource(ShapeSpec spec) : spec_(std::move(spec)), name_(describe(spec_)) {
    GmshModel model("mrsim_shape_volume");
    build(model, 0.0);
    gmsh::model::occ::getMass(3, tag_, volume_);
    model.throw_on_errors("cannot measure " + name_);
  }

  void build(GmshModel& model, double /*size*/) const override {
    tag_ = build_shape(spec_);
    gmsh::model::occ::synchronize();
    model.throw_on_errors("cannot build " + name_);
    gmsh::vectorpair volumes;
    gmsh::model::getEntities(volumes, 3);
    if (tag_ < 0 || volumes.size() != 1) throw GmshFailure(name_ + ": the parts did not fuse into one body");
  }

  double volume() const override { return volume_; }
  std::string name() const override { return name_; }

 private:
  ShapeSpec spec_;
  std::string name_;
  mutable int tag_ = -1;  // set by build(): the one volume of the current model
  double volume_ = 0.0;
};

}  // namespace

const std::vector<std::string>& shape_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& [name, info] : shape_table()) n.push_back(name);
    return n;
  }();
  return names;
}

ShapeSpec make_shape_spec(const std::string& kind, std::vector<double> dims) {
  const auto it = shape_table().find(kind);
  if (it == shape_table().end()) {
    std::string known;
    for (const auto& name : shape_names()) known += (known.empty() ? "" : ", ") + name;
    throw InputError("unknown shape '" + kind + "' (known: " + known + ")");
  }
  const ShapeInfo& info = it->second;
  if (dims.empty()) dims = info.defaults;
  if (dims.size() != info.dim_count) {
    throw InputError("shape " + kind + " takes " + std::to_string(info.dim_count) +
                     " dimension(s): --dims " + info.dims_help);
  }
  for (double v : dims) {
    if (!std::isfinite(v) || v <= 0.0) {
      throw InputError("shape " + kind + ": every dimension must be a positive number (--dims " +
                       info.dims_help + ")");
    }
  }
  return {kind, std::move(dims)};
}

std::unique_ptr<GeometrySource> make_shape_source(const ShapeSpec& spec) {
  return std::make_unique<ShapeSource>(spec);
}

}  // namespace mrsim
