#include "scenario/material.hpp"

namespace mrsim::scenario {

EngineeringParameters engineering_from_lame(const LameParameters& lame) {
  const double sum = lame.lambda + lame.mu;
  return {lame.mu * (3 * lame.lambda + 2 * lame.mu) / sum, lame.lambda / (2 * sum)};
}

LameParameters lame_from_engineering(const EngineeringParameters& e) {
  const double nu = e.poisson_ratio;
  return {e.youngs_modulus * nu / ((1 + nu) * (1 - 2 * nu)), e.youngs_modulus / (2 * (1 + nu))};
}

void add_derived_elastic_constants(nlohmann::json& material) {
  LameParameters lame;
  EngineeringParameters engineering;
  if (material.contains("lambda")) {
    lame = {material["lambda"].get<double>(), material["mu"].get<double>()};
    engineering = engineering_from_lame(lame);
  } else {
    engineering = {material["youngs_modulus"].get<double>(),
                   material["poisson_ratio"].get<double>()};
    lame = lame_from_engineering(engineering);
  }
  material["derived"] = {{"lambda", lame.lambda},
                         {"mu", lame.mu},
                         {"youngs_modulus", engineering.youngs_modulus},
                         {"poisson_ratio", engineering.poisson_ratio}};
}

}  // namespace mrsim::scenario
