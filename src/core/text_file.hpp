#pragma once
// Small text files that may legitimately be absent (a case's stderr, a folder's copy of its
// sweep file): read whole, or "" when there is none.
#include <filesystem>
#include <string>

namespace mrsim {

/// The file's bytes; "" when it cannot be opened.
std::string read_text_if_any(const std::filesystem::path& path);

}  // namespace mrsim
