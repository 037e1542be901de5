#include "simulation/calibration_cache.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/byte_record.hpp"
#include "simulation/result_cache.hpp"

namespace mrsim {

namespace {

// Bumped whenever the fit (targets, weights, pull, stopping) changes what it returns.
// 2: per_tet's local loads; 3: per_tet's seven factors per tet, sags at the finest points;
// 4: the per-tet fit without Eigen's thread-count-dependent parallel products; 5: its exp, log
// and start vectors from core/portable_math.hpp (the same bits on every processor).
constexpr int kFitVersion = 5;
constexpr std::size_t kAnyCount = std::numeric_limits<std::size_t>::max();

// Binary since 2026-12-02: as JSON, liver_probe's per-tet factors (14 000 numbers, 340 KB) took
// a fifth of its warm set-up's instructions to parse (strtod).
std::filesystem::path file_of(const std::filesystem::path& dir, const std::string& key) {
  return dir / ("level_calibration_" + key + ".bin");
}

void put(ByteRecordWriter& w, const LevelCalibration& c) {
  w.value(c.scales.components());
  w.value(c.iterations);
  w.value(static_cast<std::uint8_t>(c.local_fitted));
  w.array(c.tet_tensors);
  for (const CalibrationRatios& r : kCalibrationRatios) w.array(c.*r.member);
}

// A stiffness factor read back must be one a fit can give: positive and finite.
void check_factors(const std::array<double, 7>& factors, const char* what) {
  for (double x : factors)
    if (!(x > 0) || !std::isfinite(x)) throw std::runtime_error(what);
}

LevelCalibration get(ByteRecordReader& r, std::size_t tets) {
  LevelCalibration c;
  const auto s = r.value<std::array<double, 7>>();
  check_factors(s, "non-positive factor");
  c.scales = StiffnessScales::from_components(s);
  c.iterations = r.value<int>();
  c.local_fitted = r.value<std::uint8_t>() != 0;
  c.tet_tensors = r.array<std::array<double, 7>>(tets);
  if (!c.tet_tensors.empty() && c.tet_tensors.size() != tets)
    throw std::runtime_error("per-tet factors of another mesh");
  for (const auto& q : c.tet_tensors) check_factors(q, "a non-positive tet factor");
  for (const CalibrationRatios& ratios : kCalibrationRatios)
    c.*ratios.member = r.array<double>(kAnyCount);
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
  const bool read =
      read_cached_bytes(file_of(dir, key), key, "calibration", [&](std::string_view bytes) {
        ByteRecordReader r(bytes);
        if (r.value<std::uint64_t>() != meshes.size())
          throw std::runtime_error("another number of levels");
        for (const TetMesh* mesh : meshes) out.push_back(get(r, mesh->tets.size()));
        r.expect_end();
      });
  if (!read) return std::nullopt;
  return out;
}

void write_cached_calibration(const std::filesystem::path& dir, const std::string& key,
                              const std::vector<LevelCalibration>& calibration) {
  if (dir.empty()) return;
  ByteRecordWriter w;
  w.value(static_cast<std::uint64_t>(calibration.size()));
  for (const LevelCalibration& c : calibration) put(w, c);
  write_cached_bytes(file_of(dir, key), key, std::move(w).take(), "calibration");
}

}  // namespace mrsim
