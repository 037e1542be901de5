#pragma once
// Set-up results that depend only on a run's inputs and cost time to compute (the coarse levels'
// calibration, the levels' spectra) are kept between runs, so that sweeps and repeated runs of
// one hierarchy pay them once. One file per result under $MRSIM_CACHE_DIR/<kind>/ (default
// $XDG_CACHE_HOME/mrsim/<kind>/, else ~/.cache/mrsim/<kind>/), named by a hash of everything
// the computation reads; at most 512 files and 256 MiB per kind, the oldest going first.
// Deleting the folder is always safe: the next run computes again. Small results are JSON (the
// spectra); large ones (the calibration's per-tet factors, the hierarchy's links,
// simulation/link_cache.hpp) are binary, with a checksum: parsing them as text cost more than
// the rest of a warm set-up.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "mesh/tet_mesh.hpp"

namespace mrsim {

/// FNV-1a (64 bits) of a computation's inputs, fed field by field.
struct InputHash {
  std::uint64_t h = 14695981039346656037ull;
  void bytes(const void* p, std::size_t n);
  template <class T>
  void value(const T& v) {
    bytes(&v, sizeof v);
  }
  /// Its points and tets, with their counts.
  void mesh(const TetMesh& m);
  /// This build of mrsim (its version and its executable's size and modification time): for
  /// results whose computation may change with any edit of the code, so that a rebuild never
  /// reads what another build computed.
  void build();
  /// 16 hex digits.
  std::string hex() const;
};

/// How much a folder of results may hold before its oldest go.
struct ResultLimits {
  std::size_t files = 512;
  std::uintmax_t bytes = std::uintmax_t{256} << 20;
};

/// A folder keyed by the build grows with every rebuild: past `limits` the oldest results go,
/// down to three quarters of each limit, but never `kept` (the result just written: one result
/// larger than the limit on its own stays until the next). write_cached_result and
/// write_cached_bytes call it after each write. A result that goes is only computed again.
void prune_results(const std::filesystem::path& dir, const std::filesystem::path& kept,
                   ResultLimits limits = {});

/// The folder of one kind of cached result; empty when no folder can be named (no HOME).
std::filesystem::path result_cache_dir(std::string_view kind);

/// Hands `take` the JSON of `file` when it exists and has `key` as its "key" member; true when
/// `take` returned. A damaged file (unparsable, another key, or `take` throwing on what it
/// reads) is reported by a warning naming `what`, ignored, and false returned; so is an absent
/// one, silently.
bool read_cached_result(const std::filesystem::path& file, const std::string& key,
                        std::string_view what,
                        const std::function<void(const nlohmann::json&)>& take);

/// Stores `result` (its "key" member set to `key`) as `file`, best effort: a folder that cannot
/// be written gives a warning naming `what`, never an error. Written under a temporary name
/// unique to the process, then renamed: concurrent runs of a sweep never see a torn file.
void write_cached_result(const std::filesystem::path& file, const std::string& key,
                         nlohmann::json result, std::string_view what);

/// The binary form of read_cached_result: `file` holds a header (a magic word, `key`, the
/// payload's size and checksum) and the payload, which `take` gets when all of it checks. A
/// damaged file (short, another key or checksum, or `take` throwing on what it reads) is
/// reported by a warning naming `what`, ignored, and false returned; an absent one silently.
bool read_cached_bytes(const std::filesystem::path& file, const std::string& key,
                       std::string_view what,
                       const std::function<void(std::string_view payload)>& take);

/// Stores `payload` under `key` as `file`, as write_cached_result does (best effort, atomic).
void write_cached_bytes(const std::filesystem::path& file, const std::string& key,
                        std::string_view payload, std::string_view what);

}  // namespace mrsim
