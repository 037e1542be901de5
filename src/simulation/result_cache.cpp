#include "simulation/result_cache.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <utility>
#include <vector>

#include "core/log.hpp"
#include "core/text_file.hpp"
#include "mrsim/version.hpp"

namespace mrsim {

// Eight bytes a step, then the rest byte by byte; the shift brings the high bits down, which a
// product alone never does. Byte by byte, hashing the levels (several times a run: the
// spectra, links and calibration keys) was 1 ms of liver_probe's 30 ms set-up, one multiply's
// latency per byte.
void InputHash::bytes(const void* p, std::size_t n) {
  const auto* c = static_cast<const unsigned char*>(p);
  std::size_t k = 0;
  for (; k + 8 <= n; k += 8) {
    std::uint64_t w;
    std::memcpy(&w, c + k, 8);
    h = (h ^ w) * 1099511628211ull;
    h ^= h >> 29;
  }
  for (; k < n; ++k) h = (h ^ c[k]) * 1099511628211ull;
}

void InputHash::mesh(const TetMesh& m) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Tet) == 4 * sizeof(int),
                "points and tets hashed as contiguous arrays");
  value(m.points.size());
  bytes(m.points.data(), m.points.size() * sizeof(Vec3));
  value(m.tets.size());
  bytes(m.tets.data(), m.tets.size() * sizeof(Tet));
}

namespace {

struct ExecutableIdentity {
  bool known = false;
  std::uintmax_t size = 0;
  std::int64_t written = 0;
};

// Looked up once per process: every cache a run reads keys by it (ten a liver_probe start).
const ExecutableIdentity& executable_identity() {
  static const ExecutableIdentity identity = [] {
    ExecutableIdentity id;
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return id;
    id.size = std::filesystem::file_size(exe, ec);
    id.written = static_cast<std::int64_t>(
        std::filesystem::last_write_time(exe, ec).time_since_epoch().count());
    id.known = true;
    return id;
  }();
  return identity;
}

}  // namespace

void InputHash::build() {
  for (const std::string_view part : {std::string_view(kVersion), std::string_view(kGitRevision)})
    bytes(part.data(), part.size());
  const ExecutableIdentity& exe = executable_identity();
  if (!exe.known) return;
  value(exe.size);
  value(exe.written);
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

namespace {

bool is_result(const std::filesystem::path& p) {
  return p.extension() == ".json" || p.extension() == ".bin";
}

// `bytes` as `file`: written under a name unique to the process, then renamed, so that
// concurrent runs of a sweep never see a torn file; then the folder is pruned.
void write_atomically(const std::filesystem::path& file, std::string_view bytes,
                      std::string_view what) {
  if (file.empty()) return;
  const std::filesystem::path dir = file.parent_path();
  const std::filesystem::path tmp =
      file.string() + "." + std::to_string(static_cast<long>(::getpid())) + ".tmp";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  {
    std::ofstream out(tmp, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) ec = std::make_error_code(std::errc::io_error);
  }
  if (!ec) std::filesystem::rename(tmp, file, ec);
  if (!ec) prune_results(dir, file);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    warn("could not write the " + std::string(what) + " cache in " + dir.string() +
         " (set MRSIM_CACHE_DIR to a writable folder to keep it); the run goes on");
  }
}

void ignored(std::string_view what, const std::filesystem::path& file, const char* why) {
  warn("ignored the " + std::string(what) + " cache " + file.string() + " (" + why +
       "); computing it again");
}

// `take` run on what a cache file held: true when it returned; a throw is said and ignored.
template <class Take>
bool taken(std::string_view what, const std::filesystem::path& file, Take take) {
  try {
    take();
    return true;
  } catch (const std::exception& e) {
    ignored(what, file, e.what());
    return false;
  }
}

// The binary files' header: a magic word (it names the layout's version), the key (16 hex
// digits), the payload's size and checksum.
constexpr char kMagic[8] = {'M', 'R', 'S', 'I', 'M', 'B', 'C', '1'};
constexpr std::size_t kKeySize = 16;
constexpr std::size_t kHeaderSize = sizeof kMagic + kKeySize + 2 * sizeof(std::uint64_t);

// Catches a damaged payload (a torn copy, a flipped bit), eight bytes at a time.
std::uint64_t checksum(std::string_view bytes) {
  InputHash h;
  h.bytes(bytes.data(), bytes.size());
  return h.h;
}

}  // namespace

void prune_results(const std::filesystem::path& dir, const std::filesystem::path& kept,
                   ResultLimits limits) {
  std::error_code ec;
  struct Entry {
    std::filesystem::file_time_type written;
    std::filesystem::path path;
    std::uintmax_t size;
    bool operator<(const Entry& o) const { return written < o.written; }
  };
  std::vector<Entry> files;
  std::uintmax_t bytes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
    if (entry.is_regular_file(ec) && is_result(entry.path())) {
      files.push_back({entry.last_write_time(ec), entry.path(), entry.file_size(ec)});
      bytes += files.back().size;
    }
  if (ec || (files.size() <= limits.files && bytes <= limits.bytes)) return;
  std::sort(files.begin(), files.end());
  std::size_t left = files.size();
  for (const Entry& f : files) {
    if (left <= limits.files * 3 / 4 && bytes <= limits.bytes * 3 / 4) break;
    if (f.path == kept) continue;
    if (std::filesystem::remove(f.path, ec)) bytes -= f.size;
    --left;
  }
}

bool read_cached_result(const std::filesystem::path& file, const std::string& key,
                        std::string_view what,
                        const std::function<void(const nlohmann::json&)>& take) {
  std::error_code ec;
  if (file.empty() || !std::filesystem::is_regular_file(file, ec)) return false;
  return taken(what, file, [&] {
    const nlohmann::json j = nlohmann::json::parse(read_text_if_any(file));
    if (j.at("key").get<std::string>() != key) throw std::runtime_error("another key");
    take(j);
  });
}

void write_cached_result(const std::filesystem::path& file, const std::string& key,
                         nlohmann::json result, std::string_view what) {
  if (file.empty()) return;
  result["key"] = key;
  write_atomically(file, result.dump(1) + '\n', what);
}

bool read_cached_bytes(const std::filesystem::path& file, const std::string& key,
                       std::string_view what,
                       const std::function<void(std::string_view payload)>& take) {
  std::error_code ec;
  if (file.empty() || !std::filesystem::is_regular_file(file, ec)) return false;
  const std::string bytes = read_text_if_any(file);
  const std::string_view all(bytes);
  if (all.size() < kHeaderSize || all.substr(0, sizeof kMagic) != std::string_view(kMagic, 8)) {
    ignored(what, file, "not a result of this version");
    return false;
  }
  if (all.substr(sizeof kMagic, kKeySize) != key) {
    ignored(what, file, "another key");
    return false;
  }
  std::uint64_t size, sum;
  std::memcpy(&size, all.data() + sizeof kMagic + kKeySize, 8);
  std::memcpy(&sum, all.data() + sizeof kMagic + kKeySize + 8, 8);
  const std::string_view payload = all.substr(kHeaderSize);
  if (payload.size() != size || checksum(payload) != sum) {
    ignored(what, file, "damaged");
    return false;
  }
  return taken(what, file, [&] { take(payload); });
}

void write_cached_bytes(const std::filesystem::path& file, const std::string& key,
                        std::string_view payload, std::string_view what) {
  if (file.empty()) return;
  if (key.size() != kKeySize) throw std::logic_error("a result cache key is 16 hex digits");
  std::string bytes(kMagic, sizeof kMagic);
  bytes += key;
  const std::uint64_t size = payload.size(), sum = checksum(payload);
  bytes.append(reinterpret_cast<const char*>(&size), 8);
  bytes.append(reinterpret_cast<const char*>(&sum), 8);
  bytes += payload;
  write_atomically(file, bytes, what);
}

}  // namespace mrsim
