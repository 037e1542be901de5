#pragma once
// MRSIM_CACHE_DIR in a fresh folder of its own for a test's life (simulation/result_cache.hpp),
// the variable as it was restored after.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

class CacheFolder {
 public:
  explicit CacheFolder(const std::string& name = "cache")
      : dir_(std::filesystem::path(::testing::TempDir()) /
             ("mrsim_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(dir_);
    if (const char* old = std::getenv("MRSIM_CACHE_DIR")) saved_ = old;
    ::setenv("MRSIM_CACHE_DIR", dir_.c_str(), 1);
  }
  ~CacheFolder() {
    std::filesystem::remove_all(dir_);
    if (saved_.empty())
      ::unsetenv("MRSIM_CACHE_DIR");
    else
      ::setenv("MRSIM_CACHE_DIR", saved_.c_str(), 1);
  }
  CacheFolder(const CacheFolder&) = delete;
  CacheFolder& operator=(const CacheFolder&) = delete;
  /// The files of one kind of result.
  std::vector<std::filesystem::path> files(const std::string& kind) const {
    std::vector<std::filesystem::path> out;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir_ / kind, ec))
      out.push_back(e.path());
    return out;
  }
  /// Their file names, sorted.
  std::vector<std::string> names(const std::string& kind) const {
    std::vector<std::string> out;
    for (const auto& f : files(kind)) out.push_back(f.filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  std::filesystem::path dir_;
  std::string saved_;
};
