#pragma once
// Built-in solids for scenarios and tests that need no input file, built with gmsh's
// OpenCASCADE kernel (exact geometry, exact volume). Dimensions are in metres:
//   box        a,b,c      edge lengths, centred on the origin          (default 0.1,0.1,0.1)
//   sphere     r          centred on the origin                        (default 0.05)
//   ellipsoid  a,b,c      semi-axes, centred on the origin             (default 0.05,0.03,0.02)
//   cylinder   r,h        axis z, centred on the origin                (default 0.02,0.1)
//   beam       L,W,H      x in [0,L], y in [0,W], z in [0,H]: the validation cantilever,
//                         clamped at x = 0 in the scenarios            (default 0.1,0.02,0.02)
//   little_man s          the thesis' Fig. 5.10 "bonhomme": a belly (sphere), a head (sphere)
//                         and two arms (cylinders) fused into one body, standing on z = 0,
//                         s high overall (the head's top at 0.9 s)     (default 0.2)
#include <memory>
#include <string>
#include <vector>

#include "meshing/geometry_source.hpp"

namespace mrsim {

struct ShapeSpec {
  std::string kind;
  std::vector<double> dims;  // metres
};

/// The names accepted by --shape.
const std::vector<std::string>& shape_names();

/// Validates the kind and the dimensions (count, finite, > 0) and fills in the defaults when
/// `dims` is empty. Throws InputError.
ShapeSpec make_shape_spec(const std::string& kind, std::vector<double> dims);

std::unique_ptr<GeometrySource> make_shape_source(const ShapeSpec& spec);

}  // namespace mrsim
