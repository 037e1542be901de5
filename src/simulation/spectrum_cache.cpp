#include "simulation/spectrum_cache.hpp"

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <stdexcept>

#include "simulation/level_array_cache.hpp"
#include "simulation/result_cache.hpp"

namespace mrsim {

namespace {

// Bumped whenever what the spectra mean changes (it is in the key with the build).
constexpr int kSpectraVersion = 1;

std::string exact(double x) {
  char s[40];
  std::snprintf(s, sizeof s, "%a", x);
  return s;
}

double exact(const nlohmann::json& j, const char* name) {
  const std::string s = j.at(name).get<std::string>();
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0') throw std::runtime_error(std::string("unreadable ") + name);
  return x;
}

std::filesystem::path file_of(const std::string& key) {
  const std::filesystem::path dir = result_cache_dir("spectra");
  return dir.empty() ? dir : dir / ("level_spectra_" + key + ".json");
}

nlohmann::json to_json(const LevelSpectra& s, const TetMesh& mesh) {
  return {{"points", mesh.points.size()},      {"tets", mesh.tets.size()},
          {"stiffness", exact(s.stiffness)},   {"damping", exact(s.damping)},
          {"filtered", exact(s.filtered)},     {"combined", exact(s.combined)}};
}

std::optional<LevelSpectra> read(const std::string& key, const TetMesh& mesh) {
  LevelSpectra s;
  const bool read = read_cached_result(file_of(key), key, "level spectra", [&](const nlohmann::json& j) {
    if (j.at("points").get<std::size_t>() != mesh.points.size() ||
        j.at("tets").get<std::size_t>() != mesh.tets.size())
      throw std::runtime_error("another mesh");
    s.stiffness = exact(j, "stiffness");
    s.damping = exact(j, "damping");
    s.filtered = exact(j, "filtered");
    s.combined = exact(j, "combined");
  });
  if (!read) return std::nullopt;
  return s;
}

}  // namespace

std::string spectrum_key(const TetMesh& mesh, const MaterialLaw& law, bool semi_implicit,
                         const std::vector<std::uint8_t>& held) {
  InputHash f;
  f.value(kSpectraVersion);
  f.build();
  f.value(semi_implicit);
  f.value(law.strain);
  for (double x : {law.lambda, law.mu, law.phi, law.psi, law.density, law.scales.lambda})
    f.value(x);
  for (double x : law.scales.mu) f.value(x);
  if (law.tet_tensors) {  // object.calibration: per_tet (the keys without them stay the same)
    f.value(law.tet_tensors->size());
    f.bytes(law.tet_tensors->data(), law.tet_tensors->size() * sizeof(law.tet_tensors->front()));
  }
  f.mesh(mesh);
  f.value(held.size());
  f.bytes(held.data(), held.size());
  return f.hex();
}

LevelModel cached_level_model(const TetMesh& mesh, const MaterialLaw& law, bool semi_implicit,
                              const std::vector<std::uint8_t>& held, bool* reused) {
  const std::string key = spectrum_key(mesh, law, semi_implicit, held);
  const std::optional<LevelSpectra> known = read(key, mesh);
  if (reused) *reused = known.has_value();
  if (known) {
    std::optional<LevelArrays> arrays = read_level_arrays(key, mesh);
    LevelModel m =
        build_level_model(mesh, law, semi_implicit, held, &*known, arrays ? &*arrays : nullptr);
    if (!arrays) write_level_arrays(key, m);
    return m;
  }
  LevelModel m = build_level_model(mesh, law, semi_implicit, held);
  write_cached_result(file_of(key), key, to_json(level_spectra(m), mesh), "level spectra");
  write_level_arrays(key, m);
  return m;
}

}  // namespace mrsim
