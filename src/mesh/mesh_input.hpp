#pragma once
// Helpers shared by the mesh readers: error messages that start with the file path, and whole
// file loading. Readers parse an in-memory copy of the file so that every count announced by a
// header can be checked against the bytes that actually remain (no huge allocation from a
// lying count) and a truncated file is an error at a known place, never a read past the end.
#include <filesystem>
#include <sstream>
#include <string>
#include <string_view>

#include "core/error.hpp"

namespace mrsim {

/// Concatenates anything streamable: messages are built from paths, numbers and names.
template <class... Parts>
std::string cat(const Parts&... parts) {
  std::ostringstream out;
  out.precision(17);
  (out << ... << parts);
  return out.str();
}

/// InputError whose message starts with the file path, as every mesh error must.
InputError mesh_error(const std::filesystem::path& path, std::string_view message);

/// The whole file. Throws InputError if it is missing, not a regular file, unreadable or empty.
std::string read_whole_file(const std::filesystem::path& path);

/// Compact text for a double in messages ("3.2e-12").
std::string short_number(double value);

/// 'token' for messages, shortened and with unprintable bytes replaced: garbage files can
/// hold very long or binary "tokens".
std::string quoted_token(std::string_view token);

}  // namespace mrsim
