#pragma once
// summary.json: the figures a sweep collects from a run (product.md).
#include <filesystem>

#include <nlohmann/json.hpp>

namespace mrsim {

/// Writes `summary` atomically (temporary file + rename). Throws RunError on failure.
void write_json_file(const std::filesystem::path& file, const nlohmann::json& summary);

}  // namespace mrsim
