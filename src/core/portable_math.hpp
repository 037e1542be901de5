#pragma once
// Transcendental functions with the same bits on every x86-64 processor.
//
// glibc picks one of four builds of exp, log, sin, cos, atan2 (and Eigen's 3x3 eigen solver,
// slerp...) at load time from the processor's features (FMA, AVX, FMA4): their last bits differ,
// so a run's results depended on the machine (liver_probe's log differed in 24 datasets with
// FMA hidden by GLIBC_TUNABLES). These use only +, -, *, /, sqrt and exact bit operations,
// compiled without FMA contraction (no -march): every processor gives the same bits, so the
// golden files hold anywhere the same build runs. Within 2 ulp of the true value (tests/core/
// test_portable_math.cpp); sin and cos keep that for |x| < 1e6, beyond it they stay
// deterministic but lose accuracy (the reduction by pi/2 uses three 33-bit parts).
//
// Where a result of the simulation depends on a transcendental, call these, not std::.

namespace mrsim::portable {

double exp(double x);
double log(double x);  // natural logarithm
double sin(double x);
double cos(double x);
double atan2(double y, double x);  // IEEE 754 conventions for zeros, infinities and NaN
double acos(double x);             // NaN outside [-1, 1]

}  // namespace mrsim::portable
