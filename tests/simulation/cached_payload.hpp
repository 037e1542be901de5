#pragma once
// A result cache file (simulation/result_cache.hpp) whose payload a test rewrites and stores
// again under its own key, with a checksum that holds: only the reader's own checks can refuse
// what it then holds.
#include <cstddef>
#include <filesystem>
#include <string>

#include "core/text_file.hpp"
#include "simulation/result_cache.hpp"

template <class Edit>
void rewrite_payload(const std::filesystem::path& file, Edit edit) {
  const std::string bytes = mrsim::read_text_if_any(file);
  constexpr std::size_t kHeader = 8 + 16 + 16;  // magic, key, size, checksum
  std::string payload = bytes.substr(kHeader);
  edit(payload);
  const std::string name = file.stem().string();
  mrsim::write_cached_bytes(file, name.substr(name.rfind('_') + 1), payload, "test");
}
