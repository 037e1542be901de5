#pragma once
#include <Eigen/Dense>

namespace mrsim {
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
}  // namespace mrsim
