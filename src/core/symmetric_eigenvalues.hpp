#pragma once
#include "core/vec.hpp"

namespace mrsim {

/// The eigenvalues of a symmetric 3x3 matrix (its lower triangle is read), ascending: the
/// trigonometric solution of the characteristic cubic, on the matrix shifted by its mean
/// eigenvalue and scaled into [-1, 1] (no overflow, and a zero-trace cubic). Eigen's
/// SelfAdjointEigenSolver::computeDirect does the same with libm's atan2, cos and sin, whose
/// last bits depend on the processor; this one uses core/portable_math.hpp, so the strain and
/// stable-step bounds built on it have the same bits on every machine.
Vec3 symmetric_eigenvalues(const Mat3& m);

}  // namespace mrsim
