#include "simulation/calibration_cache.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>

#include "core/log.hpp"
#include "core/text_file.hpp"

namespace mrsim {

namespace {

// Bumped whenever the fit (targets, weights, pull, stopping) changes what it returns.
constexpr int kFitVersion = 1;

struct Fnv {
  std::uint64_t h = 14695981039346656037ull;
  void bytes(const void* p, std::size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    for (std::size_t k = 0; k < n; ++k) h = (h ^ c[k]) * 1099511628211ull;
  }
  template <class T>
  void value(const T& v) {
    bytes(&v, sizeof v);
  }
};

std::filesystem::path file_of(const std::filesystem::path& dir, const std::string& key) {
  return dir / ("level_calibration_" + key + ".json");
}

nlohmann::json to_json(const LevelCalibration& c) {
  nlohmann::json j = {{"scales", c.scales.components()}, {"iterations", c.iterations}};
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
  for (const CalibrationRatios& r : kCalibrationRatios)
    c.*r.member = j.at(std::string(r.quantity) + "_" + r.when).get<std::vector<double>>();
  c.iterations = j.at("iterations").get<int>();
  return c;
}

}  // namespace

std::string calibration_key(const std::vector<const TetMesh*>& meshes, const MaterialLaw& law,
                            const std::vector<std::vector<std::uint8_t>>& fixed) {
  Fnv f;
  f.value(kFitVersion);
  f.value(law.lambda);
  f.value(law.mu);
  f.value(law.density);
  f.value(meshes.size());
  for (std::size_t l = 0; l < meshes.size(); ++l) {
    const TetMesh& m = *meshes[l];
    f.value(m.points.size());
    for (const Vec3& p : m.points) f.bytes(p.data(), 3 * sizeof(double));
    f.value(m.tets.size());
    for (const Tet& t : m.tets) f.bytes(t.data(), sizeof(Tet));
    const std::vector<std::uint8_t> none;
    const std::vector<std::uint8_t>& held = l < fixed.size() ? fixed[l] : none;
    f.value(held.size());
    f.bytes(held.data(), held.size());
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(f.h));
  return hex;
}

std::filesystem::path calibration_cache_dir() {
  if (const char* dir = std::getenv("MRSIM_CACHE_DIR"); dir && *dir)
    return std::filesystem::path(dir) / "calibration";
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return std::filesystem::path(xdg) / "mrsim" / "calibration";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".cache" / "mrsim" / "calibration";
  return {};
}

std::optional<std::vector<LevelCalibration>> read_cached_calibration(
    const std::filesystem::path& dir, const std::string& key, std::size_t levels) {
  if (dir.empty()) return std::nullopt;
  const std::filesystem::path file = file_of(dir, key);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(read_text_if_any(file));
    if (j.at("key").get<std::string>() != key) throw std::runtime_error("another key");
    std::vector<LevelCalibration> out;
    for (const nlohmann::json& level : j.at("levels")) out.push_back(from_json(level));
    if (out.size() != levels) throw std::runtime_error("another number of levels");
    return out;
  } catch (const std::exception& e) {
    warn("ignored the calibration cache " + file.string() + " (" + e.what() +
         "); computing the calibration again");
    return std::nullopt;
  }
}

void write_cached_calibration(const std::filesystem::path& dir, const std::string& key,
                              const std::vector<LevelCalibration>& calibration) {
  if (dir.empty()) return;
  nlohmann::json j = {{"key", key}, {"levels", nlohmann::json::array()}};
  for (const LevelCalibration& c : calibration) j["levels"].push_back(to_json(c));
  const std::filesystem::path file = file_of(dir, key);
  const std::filesystem::path tmp =
      file.string() + "." + std::to_string(static_cast<long>(::getpid())) + ".tmp";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  {
    std::ofstream out(tmp);
    out << j.dump(1) << '\n';
    out.close();
    if (!out) ec = std::make_error_code(std::errc::io_error);
  }
  if (!ec) std::filesystem::rename(tmp, file, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    warn("could not write the calibration cache in " + dir.string() +
         " (set MRSIM_CACHE_DIR to a writable folder to keep it); the run goes on");
  }
}

}  // namespace mrsim
