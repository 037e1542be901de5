#include "mesh/mesh_input.hpp"

#include <cstdio>
#include <fstream>
#include <system_error>

namespace mrsim {

InputError mesh_error(const std::filesystem::path& path, std::string_view message) {
  return InputError(cat(path.string(), ": ", message));
}

std::string read_whole_file(const std::filesystem::path& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) throw mesh_error(path, "file not found");
  if (!std::filesystem::is_regular_file(status)) throw mesh_error(path, "not a regular file");
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw mesh_error(path, cat("cannot read the file size: ", ec.message()));
  if (size == 0) throw mesh_error(path, "file is empty");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw mesh_error(path, "cannot open the file for reading");
  std::string bytes(size, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  // Fewer bytes than announced means the file shrank under us: parse what we have.
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  if (bytes.empty()) throw mesh_error(path, "file is empty");
  return bytes;
}

std::string short_number(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", value);
  return buf;
}

std::string quoted_token(std::string_view token) {
  constexpr std::size_t kShown = 40;
  std::string out = "'";
  for (char c : token.substr(0, kShown)) out += (c >= 32 && c < 127) ? c : '?';
  if (token.size() > kShown) out += "...";
  return out + "'";
}

}  // namespace mrsim
