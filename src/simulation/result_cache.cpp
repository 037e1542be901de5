#include "simulation/result_cache.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <system_error>
#include <utility>
#include <vector>

#include "core/log.hpp"
#include "core/text_file.hpp"
#include "mrsim/version.hpp"

namespace mrsim {

void InputHash::bytes(const void* p, std::size_t n) {
  const auto* c = static_cast<const unsigned char*>(p);
  for (std::size_t k = 0; k < n; ++k) h = (h ^ c[k]) * 1099511628211ull;
}

void InputHash::mesh(const TetMesh& m) {
  value(m.points.size());
  for (const Vec3& p : m.points) bytes(p.data(), 3 * sizeof(double));
  value(m.tets.size());
  for (const Tet& t : m.tets) bytes(t.data(), sizeof(Tet));
}

void InputHash::build() {
  for (const std::string_view part : {std::string_view(kVersion), std::string_view(kGitRevision)})
    bytes(part.data(), part.size());
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return;
  const auto size = std::filesystem::file_size(exe, ec);
  const auto written = std::filesystem::last_write_time(exe, ec).time_since_epoch().count();
  value(size);
  value(written);
}

std::string InputHash::hex() const {
  char out[17];
  std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h));
  return out;
}

std::filesystem::path result_cache_dir(std::string_view kind) {
  if (const char* dir = std::getenv("MRSIM_CACHE_DIR"); dir && *dir)
    return std::filesystem::path(dir) / kind;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return std::filesystem::path(xdg) / "mrsim" / kind;
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".cache" / "mrsim" / kind;
  return {};
}

bool read_cached_result(const std::filesystem::path& file, const std::string& key,
                        std::string_view what,
                        const std::function<void(const nlohmann::json&)>& take) {
  std::error_code ec;
  if (file.empty() || !std::filesystem::is_regular_file(file, ec)) return false;
  try {
    const nlohmann::json j = nlohmann::json::parse(read_text_if_any(file));
    if (j.at("key").get<std::string>() != key) throw std::runtime_error("another key");
    take(j);
    return true;
  } catch (const std::exception& e) {
    warn("ignored the " + std::string(what) + " cache " + file.string() + " (" + e.what() +
         "); computing it again");
    return false;
  }
}

namespace {

// A folder keyed by the build grows with every rebuild: past kMostFiles results the oldest go,
// down to three quarters of it. A result that goes is only computed again.
constexpr std::size_t kMostFiles = 512;

void prune(const std::filesystem::path& dir) {
  std::error_code ec;
  std::vector<std::pair<std::filesystem::file_time_type, std::filesystem::path>> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
    if (entry.is_regular_file(ec) && entry.path().extension() == ".json")
      files.emplace_back(entry.last_write_time(ec), entry.path());
  if (ec || files.size() <= kMostFiles) return;
  std::sort(files.begin(), files.end());
  for (std::size_t k = 0; k + kMostFiles * 3 / 4 < files.size(); ++k)
    std::filesystem::remove(files[k].second, ec);
}

}  // namespace

void write_cached_result(const std::filesystem::path& file, const std::string& key,
                         nlohmann::json result, std::string_view what) {
  if (file.empty()) return;
  result["key"] = key;
  const std::filesystem::path dir = file.parent_path();
  const std::filesystem::path tmp =
      file.string() + "." + std::to_string(static_cast<long>(::getpid())) + ".tmp";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  {
    std::ofstream out(tmp);
    out << result.dump(1) << '\n';
    out.close();
    if (!out) ec = std::make_error_code(std::errc::io_error);
  }
  if (!ec) std::filesystem::rename(tmp, file, ec);
  if (!ec) prune(dir);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    warn("could not write the " + std::string(what) + " cache in " + dir.string() +
         " (set MRSIM_CACHE_DIR to a writable folder to keep it); the run goes on");
  }
}

}  // namespace mrsim
