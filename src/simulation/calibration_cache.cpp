#include "simulation/calibration_cache.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "simulation/result_cache.hpp"

namespace mrsim {

namespace {

// Bumped whenever the fit (targets, weights, pull, stopping) changes what it returns.
// 2: per_tet's local loads; 3: per_tet's seven factors per tet, sags at the finest points;
// 4: the per-tet fit without Eigen's thread-count-dependent parallel products.
constexpr int kFitVersion = 4;

std::filesystem::path file_of(const std::filesystem::path& dir, const std::string& key) {
  return dir / ("level_calibration_" + key + ".json");
}

nlohmann::json to_json(const LevelCalibration& c) {
  nlohmann::json j = {{"scales", c.scales.components()}, {"iterations", c.iterations}};
  if (!c.tet_tensors.empty()) j["tet_tensors"] = c.tet_tensors;
  j["local_fitted"] = c.local_fitted;
  for (const CalibrationRatios& r : kCalibrationRatios)
    j[std::string(r.quantity) + "_" + r.when] = c.*r.member;
  return j;
}

LevelCalibration from_json(const nlohmann::json& j) {
  LevelCalibration c;
  const auto s = j.at("scales").get<std::array<double, 7>>();
  for (double x : s)
    if (!(x > 0)) throw std::runtime_error("non-positive factor");
  c.scales = StiffnessScales::from_components(s);
  if (j.contains("tet_tensors")) {
    c.tet_tensors = j.at("tet_tensors").get<TetTensors>();
    for (const auto& q : c.tet_tensors)
      for (double x : q)
        if (!(x > 0) || !std::isfinite(x)) throw std::runtime_error("a non-positive tet factor");
  }
  for (const CalibrationRatios& r : kCalibrationRatios)
    c.*r.member = j.at(std::string(r.quantity) + "_" + r.when).get<std::vector<double>>();
  c.iterations = j.at("iterations").get<int>();
  c.local_fitted = j.at("local_fitted").get<bool>();
  return c;
}

}  // namespace

std::string calibration_key(const std::vector<const TetMesh*>& meshes, const MaterialLaw& law,
                            const std::vector<std::vector<std::uint8_t>>& fixed,
                            CalibrationKind kind) {
  InputHash f;
  f.value(kFitVersion);
  // The level-wide fit's keys stay what they were; the per-tet fit has its own.
  if (kind == CalibrationKind::PerTet) f.value(kind);
  f.value(law.lambda);
  f.value(law.mu);
  f.value(law.density);
  f.value(meshes.size());
  for (std::size_t l = 0; l < meshes.size(); ++l) {
    f.mesh(*meshes[l]);
    const std::vector<std::uint8_t> none;
    const std::vector<std::uint8_t>& held = l < fixed.size() ? fixed[l] : none;
    f.value(held.size());
    f.bytes(held.data(), held.size());
  }
  return f.hex();
}

std::filesystem::path calibration_cache_dir() { return result_cache_dir("calibration"); }

std::optional<std::vector<LevelCalibration>> read_cached_calibration(
    const std::filesystem::path& dir, const std::string& key,
    const std::vector<const TetMesh*>& meshes) {
  if (dir.empty()) return std::nullopt;
  std::vector<LevelCalibration> out;
  const bool read = read_cached_result(file_of(dir, key), key, "calibration", [&](const nlohmann::json& j) {
    for (const nlohmann::json& level : j.at("levels")) out.push_back(from_json(level));
    if (out.size() != meshes.size()) throw std::runtime_error("another number of levels");
    for (std::size_t l = 0; l < out.size(); ++l)
      if (!out[l].tet_tensors.empty() && out[l].tet_tensors.size() != meshes[l]->tets.size())
        throw std::runtime_error("per-tet factors of another mesh");
  });
  if (!read) return std::nullopt;
  return out;
}

void write_cached_calibration(const std::filesystem::path& dir, const std::string& key,
                              const std::vector<LevelCalibration>& calibration) {
  if (dir.empty()) return;
  nlohmann::json j = {{"levels", nlohmann::json::array()}};
  for (const LevelCalibration& c : calibration) j["levels"].push_back(to_json(c));
  write_cached_result(file_of(dir, key), key, std::move(j), "calibration");
}

}  // namespace mrsim
