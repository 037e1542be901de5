// Lamé (lambda, mu) <-> engineering (E, nu) conversions and the derived constants.
#include "scenario/material.hpp"

#include <gtest/gtest.h>

namespace mrsim::scenario {
namespace {

TEST(Material, EngineeringFromLameMatchesTextbookValues) {
  // Steel-like: E = 200 GPa, nu = 0.3 <=> lambda = 115.38 GPa, mu = 76.92 GPa.
  const auto e = engineering_from_lame({115.384615384615e9, 76.9230769230769e9});
  EXPECT_NEAR(e.youngs_modulus, 200e9, 200e9 * 1e-9);
  EXPECT_NEAR(e.poisson_ratio, 0.3, 1e-12);
}

TEST(Material, LameFromEngineeringMatchesTextbookValues) {
  const auto l = lame_from_engineering({200e9, 0.3});
  EXPECT_NEAR(l.lambda, 200e9 * 0.3 / (1.3 * 0.4), 1e-3);
  EXPECT_NEAR(l.mu, 200e9 / 2.6, 1e-3);
}

TEST(Material, ConversionsAreInverse) {
  // Near incompressibility (lambda >> mu) nu -> 0.5 and 1 - 2 nu cancels: the E, nu form is
  // ill-conditioned there, so the pairs stay within lambda / mu <= 1e4.
  for (const double lambda : {0.0, 1.0e3, 5.0e4, 3.0e7})
    for (const double mu : {3.0e3, 1.0e4, 2.5e8}) {
      const auto back = lame_from_engineering(engineering_from_lame({lambda, mu}));
      EXPECT_NEAR(back.lambda, lambda, 1e-9 * (lambda + mu));
      EXPECT_NEAR(back.mu, mu, 1e-9 * mu);
    }
}

TEST(Material, ZeroPoissonRatioMeansZeroLambda) {
  const auto l = lame_from_engineering({1.0e5, 0.0});
  EXPECT_EQ(l.lambda, 0.0);
  EXPECT_DOUBLE_EQ(l.mu, 0.5e5);
}

TEST(Material, DerivedConstantsFromEitherPair) {
  nlohmann::json lame = {{"lambda", 5.0e4}, {"mu", 1.0e4}};
  add_derived_elastic_constants(lame);
  EXPECT_DOUBLE_EQ(lame["derived"]["lambda"].get<double>(), 5.0e4);
  EXPECT_DOUBLE_EQ(lame["derived"]["youngs_modulus"].get<double>(), 1.0e4 * 17.0e4 / 6.0e4);
  EXPECT_DOUBLE_EQ(lame["derived"]["poisson_ratio"].get<double>(), 5.0 / 12.0);
  EXPECT_FALSE(lame.contains("youngs_modulus"));  // the user's choice stays as written

  nlohmann::json engineering = {{"youngs_modulus", 1.0e5}, {"poisson_ratio", 0.25}};
  add_derived_elastic_constants(engineering);
  EXPECT_DOUBLE_EQ(engineering["derived"]["lambda"].get<double>(), 1.0e5 * 0.25 / (1.25 * 0.5));
  EXPECT_DOUBLE_EQ(engineering["derived"]["mu"].get<double>(), 1.0e5 / 2.5);
  EXPECT_DOUBLE_EQ(engineering["derived"]["youngs_modulus"].get<double>(), 1.0e5);
}

}  // namespace
}  // namespace mrsim::scenario
