#include "scenario/did_you_mean.hpp"

#include <gtest/gtest.h>

namespace mrsim::scenario {
namespace {

TEST(DidYouMean, EditDistance) {
  EXPECT_EQ(edit_distance("evry", "every"), 1u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("Lambda", "lambda"), 0u);
}

TEST(DidYouMean, SuggestsPlausibleTyposOnly) {
  const std::vector<std::string> keys = {"dir", "every", "vtk"};
  EXPECT_EQ(closest_match("evry", keys), "every");
  EXPECT_EQ(closest_match("vtx", keys), "vtk");
  EXPECT_EQ(closest_match("xyz", keys), std::nullopt);
  EXPECT_EQ(closest_match("poisson", {"lambda", "poisson_ratio"}), "poisson_ratio");
  EXPECT_EQ(closest_match("integrater", {"integrator", "substeps"}), "integrator");
  EXPECT_EQ(closest_match("anything", {}), std::nullopt);
}

}  // namespace
}  // namespace mrsim::scenario
