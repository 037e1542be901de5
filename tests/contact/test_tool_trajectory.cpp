#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "contact/tool_trajectory.hpp"
#include "core/error.hpp"
#include "support/scratch_and_shared.hpp"

using namespace mrsim;

namespace {

constexpr double kPi = std::numbers::pi;

Quat rot(double angle, const Vec3& axis) {
  return Quat(Eigen::AngleAxisd(angle, axis.normalized()));
}

// Angle between two orientations (either quaternion sign).
double angle_between(const Quat& a, const Quat& b) { return a.angularDistance(b); }

Keyframe key(double t, const Vec3& p, const Quat& q = Quat::Identity()) {
  Keyframe k;
  k.t = t;
  k.position = p;
  k.orientation = q;
  return k;
}

std::vector<Keyframe> sample_keys() {
  return {key(0.0, Vec3(0, 0, 1), Quat::Identity()),
          key(0.4, Vec3(0.2, 0.1, 0.6), rot(0.7, Vec3(1, 0, 0))),
          key(1.0, Vec3(0.5, -0.3, 0.2), rot(1.2, Vec3(1, 1, 0)) * rot(0.3, Vec3(0, 0, 1))),
          key(1.3, Vec3(0.1, 0.0, 0.4), rot(2.0, Vec3(0, 1, 1)))};
}

// Central differences of position and orientation (relative rotation in the world frame).
Vec3 fd_velocity(const ToolTrajectory& tr, double t, double h) {
  return (tr.pose(t + h).position - tr.pose(t - h).position) / (2 * h);
}

Vec3 fd_angular_velocity(const ToolTrajectory& tr, double t, double h) {
  const Quat rel = tr.pose(t + h).orientation * tr.pose(t - h).orientation.conjugate();
  const Eigen::AngleAxisd aa(rel);
  return aa.axis() * aa.angle() / (2 * h);
}

template <class F>
void expect_throws_with(F&& f, const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    for (const auto& part : parts) EXPECT_NE(msg.find(part), std::string::npos) << msg;
  }
}

}  // namespace

TEST(ToolTrajectory, RejectsBadKeyframes) {
  const std::string what = "tools[0].trajectory";
  auto make = [&](std::vector<Keyframe> keys) {
    return [&what, keys] { ToolTrajectory(keys, Interpolation::Linear, what); };
  };
  expect_throws_with(make({}), {what + ": "});
  try {
    ToolTrajectory({key(0, Vec3::Zero()), key(0.5, Vec3::Zero()), key(0.5, Vec3::Zero())},
                   Interpolation::Smooth, what);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "tools[0].trajectory: keyframe 2 time 0.5 s is not after 0.5 s");
  }
  expect_throws_with(make({key(1, Vec3::Zero()), key(0.5, Vec3::Zero())}), {what, "keyframe 1"});
  Keyframe zero_q = key(1, Vec3::Zero(), Quat(0, 0, 0, 0));
  expect_throws_with(make({key(0, Vec3::Zero()), zero_q}), {what, "keyframe 1", "zero"});
  Keyframe nan_q = key(1, Vec3::Zero(), Quat(NAN, 0, 0, 1));
  expect_throws_with(make({nan_q}), {what, "keyframe 0"});
  expect_throws_with(make({key(0, Vec3(0, INFINITY, 0))}), {what, "keyframe 0"});
  expect_throws_with(make({key(NAN, Vec3::Zero())}), {what, "keyframe 0"});
}

TEST(ToolTrajectory, NormalisesAndFlipsQuaternions) {
  const Quat a = rot(0.3, Vec3::UnitZ());
  Quat b = rot(0.5, Vec3::UnitZ());
  b.coeffs() *= -3.0;  // same rotation, other hemisphere, not unit
  const ToolTrajectory tr({key(0, Vec3::Zero(), Quat(a.coeffs() * 2.0)), key(1, Vec3::Zero(), b)},
                          Interpolation::Linear, "t");
  EXPECT_NEAR(tr.keys()[0].orientation.norm(), 1, 1e-15);
  EXPECT_NEAR(tr.keys()[1].orientation.norm(), 1, 1e-15);
  EXPECT_GT(tr.keys()[0].orientation.dot(tr.keys()[1].orientation), 0);
  // Short way: halfway is a turn of 0.4 about z, not the long way round.
  EXPECT_LT(angle_between(tr.pose(0.5).orientation, rot(0.4, Vec3::UnitZ())), 1e-12);
  EXPECT_NEAR(tr.pose(0.5).angular_velocity.z(), 0.2, 1e-12);
}

TEST(ToolTrajectory, OneKeyframeIsConstant) {
  const Quat q = rot(0.8, Vec3(1, 2, 3));
  for (auto interp : {Interpolation::Linear, Interpolation::Smooth}) {
    const ToolTrajectory tr({key(2.0, Vec3(1, 2, 3), q)}, interp, "t");
    for (double t : {-5.0, 2.0, 7.0}) {
      const ToolPose p = tr.pose(t);
      EXPECT_EQ(p.position, Vec3(1, 2, 3));
      EXPECT_LT(angle_between(p.orientation, q), 1e-15);
      EXPECT_EQ(p.velocity, Vec3::Zero());
      EXPECT_EQ(p.angular_velocity, Vec3::Zero());
    }
  }
}

TEST(ToolTrajectory, HitsKeyframesAndClamps) {
  for (auto interp : {Interpolation::Linear, Interpolation::Smooth}) {
    const ToolTrajectory tr(sample_keys(), interp, "t");
    for (const Keyframe& k : tr.keys()) {
      const ToolPose p = tr.pose(k.t);
      EXPECT_LT((p.position - k.position).norm(), 1e-14) << "t=" << k.t;
      EXPECT_LT(angle_between(p.orientation, k.orientation), 1e-12) << "t=" << k.t;
    }
    for (double t : {-1.0, -1e-9}) {
      const ToolPose p = tr.pose(t);
      EXPECT_EQ(p.position, tr.keys().front().position);
      EXPECT_EQ(p.velocity, Vec3::Zero());
      EXPECT_EQ(p.angular_velocity, Vec3::Zero());
    }
    for (double t : {1.3, 1.3 + 1e-9, 10.0}) {
      const ToolPose p = tr.pose(t);
      EXPECT_EQ(p.position, tr.keys().back().position);
      EXPECT_EQ(p.velocity, Vec3::Zero());
      EXPECT_EQ(p.angular_velocity, Vec3::Zero());
    }
    EXPECT_EQ(tr.pose(NAN).position, tr.keys().front().position);  // never NaN
  }
}

TEST(ToolTrajectory, LinearMidpointAndSlope) {
  const Quat quarter_turn = rot(kPi / 2, Vec3::UnitZ());
  const ToolTrajectory tr({key(1, Vec3(0, 0, 1)), key(3, Vec3(2, -4, 0), quarter_turn)},
                          Interpolation::Linear, "t");
  const ToolPose mid = tr.pose(2);
  EXPECT_LT((mid.position - Vec3(1, -2, 0.5)).norm(), 1e-15);
  EXPECT_LT((mid.velocity - Vec3(1, -2, -0.5)).norm(), 1e-15);
  EXPECT_LT(angle_between(mid.orientation, rot(kPi / 4, Vec3::UnitZ())), 1e-12);
  EXPECT_LT((mid.angular_velocity - Vec3(0, 0, kPi / 4)).norm(), 1e-12);
  // Quarter way: a quarter of the turn (slerp is uniform in angle).
  EXPECT_LT(angle_between(tr.pose(1.5).orientation, rot(kPi / 8, Vec3::UnitZ())), 1e-12);
}

TEST(ToolTrajectory, OrientationIsContinuousAtKeys) {
  for (auto interp : {Interpolation::Linear, Interpolation::Smooth}) {
    const ToolTrajectory tr(sample_keys(), interp, "t");
    for (const Keyframe& k : tr.keys()) {
      EXPECT_LT(angle_between(tr.pose(k.t - 1e-9).orientation, k.orientation), 1e-7) << k.t;
      EXPECT_LT((tr.pose(k.t - 1e-9).position - k.position).norm(), 1e-7) << k.t;
    }
  }
}

TEST(ToolTrajectory, AngularVelocityIsInTheWorldFrame) {
  // Tilted tool (its z axis along world -y) turning by 0.6 rad about the world z axis.
  const Quat q0 = rot(kPi / 2, Vec3::UnitX());
  const Quat q1 = rot(0.6, Vec3::UnitZ()) * q0;
  const ToolTrajectory tr({key(0, Vec3::Zero(), q0), key(2, Vec3::Zero(), q1)},
                          Interpolation::Linear, "t");
  EXPECT_LT((tr.pose(0.7).angular_velocity - Vec3(0, 0, 0.3)).norm(), 1e-12);
  EXPECT_LT(angle_between(tr.pose(1).orientation, rot(0.3, Vec3::UnitZ()) * q0), 1e-12);
}

TEST(ToolTrajectory, VelocitiesMatchFiniteDifferences) {
  for (auto interp : {Interpolation::Linear, Interpolation::Smooth}) {
    SCOPED_TRACE(interp == Interpolation::Linear ? "linear" : "smooth");
    const ToolTrajectory tr(sample_keys(), interp, "t");
    const double h = 1e-6;
    for (double t = 0.013; t < 1.3; t += 0.0417) {
      bool near_key = false;
      for (const Keyframe& k : tr.keys()) near_key |= std::abs(t - k.t) < 2 * h;
      if (near_key) continue;  // the linear velocity jumps there
      const ToolPose p = tr.pose(t);
      EXPECT_LT((p.velocity - fd_velocity(tr, t, h)).norm(), 1e-6) << "t=" << t;
      EXPECT_LT((p.angular_velocity - fd_angular_velocity(tr, t, h)).norm(), 1e-6) << "t=" << t;
      EXPECT_NEAR(p.orientation.norm(), 1, 1e-14);
    }
  }
}

TEST(ToolTrajectory, SmoothIsC1WithCatmullRomTangents) {
  const ToolTrajectory tr(sample_keys(), Interpolation::Smooth, "t");
  const auto& k = tr.keys();
  const double e = 1e-9;
  for (std::size_t i = 1; i + 1 < k.size(); ++i) {
    const Vec3 expected = (k[i + 1].position - k[i - 1].position) / (k[i + 1].t - k[i - 1].t);
    EXPECT_LT((tr.pose(k[i].t - e).velocity - expected).norm(), 1e-6) << "key " << i;
    EXPECT_LT((tr.pose(k[i].t + e).velocity - expected).norm(), 1e-6) << "key " << i;
    EXPECT_LT((tr.pose(k[i].t).velocity - expected).norm(), 1e-12) << "key " << i;
    // Eased orientations: at rest at every key, continuously.
    EXPECT_LT(tr.pose(k[i].t - e).angular_velocity.norm(), 1e-6);
    EXPECT_LT(tr.pose(k[i].t + e).angular_velocity.norm(), 1e-6);
  }
  // Starts and stops at rest, without a jump.
  EXPECT_LT(tr.pose(k.front().t + e).velocity.norm(), 1e-6);
  EXPECT_LT(tr.pose(k.back().t - e).velocity.norm(), 1e-6);
  // Finite-difference velocity is continuous everywhere: no step larger than a smooth one.
  double max_jump = 0;
  Vec3 previous = fd_velocity(tr, 0.001, 1e-7);
  for (double t = 0.002; t < 1.299; t += 0.001) {
    const Vec3 v = fd_velocity(tr, t, 1e-7);
    max_jump = std::max(max_jump, (v - previous).norm());
    previous = v;
  }
  EXPECT_LT(max_jump, 0.05);
}

TEST(ToolTrajectory, SmoothPositionIsHermite) {
  // Two keys: zero end tangents, so x(u) = 3u^2 - 2u^3 of the way (u = 1/4 -> 5/32).
  const ToolTrajectory tr({key(0, Vec3::Zero()), key(2, Vec3(3.2, 0, 0), rot(1.0, Vec3::UnitX()))},
                          Interpolation::Smooth, "t");
  const ToolPose p = tr.pose(0.5);
  EXPECT_NEAR(p.position.x(), 3.2 * 5.0 / 32.0, 1e-14);
  EXPECT_NEAR(p.velocity.x(), 3.2 * (6 * 0.25 - 6 * 0.0625) / 2.0, 1e-14);
  EXPECT_LT(angle_between(p.orientation, rot(5.0 / 32.0, Vec3::UnitX())), 1e-12);
  EXPECT_NEAR(p.angular_velocity.x(), (6 * 0.25 - 6 * 0.0625) / 2.0, 1e-12);
}

TEST(ToolPose, LocalWorldRoundTrip) {
  ToolPose p;
  p.position = Vec3(1, -2, 0.5);
  p.orientation = rot(0.9, Vec3(1, 1, 2));
  p.velocity = Vec3(0.1, 0, 0);
  p.angular_velocity = Vec3(0, 0, 2);
  const Vec3 x(0.3, 0.7, -1.1);
  EXPECT_LT((p.to_world(p.to_local(x)) - x).norm(), 1e-14);
  EXPECT_LT((p.velocity_at(p.position + Vec3(1, 0, 0)) - Vec3(0.1, 2, 0)).norm(), 1e-15);
}

// ---- CSV recordings ----

namespace {

std::vector<Keyframe> read_csv(const test::ScratchDir& dir, const std::string& text) {
  return read_trajectory_csv(dir.write("traj.csv", text));
}

void expect_csv_error(const std::string& text, int line, const std::string& reason) {
  const test::ScratchDir dir;
  const auto file = dir.write("bad.csv", text);
  expect_throws_with([&] { read_trajectory_csv(file); },
                     {file.string() + ":" + std::to_string(line) + ": ", reason});
}

}  // namespace

TEST(TrajectoryCsv, ReadsHeaderCommentsAndBlankLines) {
  const test::ScratchDir dir;
  const auto keys = read_csv(dir,
                             "# recorded by the haptic device\n"
                             "t, x, y, z, qw, qx, qy, qz\n"
                             "\n"
                             "0.0, 0, 0, 0.1, 1, 0, 0, 0   # start\r\n"
                             "   \t\n"
                             "0.5,1e-3,-2E-3,+0.05,0,0,0,2\n"
                             "# end\n");
  ASSERT_EQ(keys.size(), 2u);
  EXPECT_EQ(keys[0].t, 0.0);
  EXPECT_EQ(keys[0].position, Vec3(0, 0, 0.1));
  EXPECT_EQ(keys[1].t, 0.5);
  EXPECT_EQ(keys[1].position, Vec3(1e-3, -2e-3, 0.05));
  EXPECT_LT(angle_between(keys[1].orientation, rot(kPi, Vec3::UnitZ())), 1e-15);
  EXPECT_NEAR(keys[1].orientation.norm(), 1, 1e-15);  // normalised
}

TEST(TrajectoryCsv, ReadsWhitespaceSeparatedPositionsOnly) {
  const test::ScratchDir dir;
  const auto keys = read_csv(dir, "0 1 2 3\n0.25\t4  5\t 6\n1.5 7 8 9");  // no final newline
  ASSERT_EQ(keys.size(), 3u);
  EXPECT_EQ(keys[1].position, Vec3(4, 5, 6));
  EXPECT_EQ(keys[2].t, 1.5);
  EXPECT_EQ(keys[2].position, Vec3(7, 8, 9));
  for (const Keyframe& k : keys) EXPECT_EQ(k.orientation.coeffs(), Quat::Identity().coeffs());
  // A recording feeds a trajectory directly.
  const ToolTrajectory tr(keys, Interpolation::Linear, "tools[0].trajectory");
  EXPECT_LT((tr.pose(0.125).position - Vec3(2.5, 3.5, 4.5)).norm(), 1e-14);
}

TEST(TrajectoryCsv, ErrorsNameTheLine) {
  expect_csv_error("t,x,y,z\n0,0,0,0\n1,0,abc,0\n", 3, "not a number");
  expect_csv_error("0,0,0,0\n\n1,0,,0\n", 3, "not a number");
  expect_csv_error("0,0,0,0\n1,0,0,0,5\n", 2, "found 5");
  expect_csv_error("# c\n0 0 0 0\n1 0 0 0 1 0 0 0\n", 3, "columns");
  expect_csv_error("0,0,0,0\n0.5,0,0,0\n0.5,1,0,0\n", 3, "time 0.5 s is not after 0.5 s");
  expect_csv_error("0,0,0,0\n0.5,0,0,0\n0.2,1,0,0\n", 3, "not after");
  expect_csv_error("0,0,0,0\n1,nan,0,0\n", 2, "not finite");
  expect_csv_error("0,0,0,0\n1,0,inf,0\n", 2, "not finite");
  expect_csv_error("t x y z qw qx qy qz\n0 0 0 0 0 0 0 0\n", 2, "quaternion is zero");
  expect_csv_error("0,0,0,0\nt,x,y,z\n", 2, "not a number");  // a header only comes first
  expect_csv_error("t,x,y,z\nt,x,y,z\n", 2, "not a number");
  expect_csv_error("0,0,0,0\n1,2,3\n", 2, "found 3");
  expect_csv_error("0,0,0,0\n1;2;3;4\n", 2, "found 1");
}

TEST(TrajectoryCsv, EmptyOrMissingFilesNameTheFile) {
  const test::ScratchDir dir;
  const auto header_only = dir.write("header.csv", "# nothing recorded\nt,x,y,z\n\n");
  expect_throws_with([&] { read_trajectory_csv(header_only); },
                     {header_only.string(), "no sample"});
  const auto missing = dir.file("missing.csv");
  expect_throws_with([&] { read_trajectory_csv(missing); }, {missing.string()});
  expect_throws_with([&] { read_trajectory_csv(dir.path()); }, {dir.path().string()});
}
