#include "core/text_file.hpp"

#include <fstream>
#include <sstream>

namespace mrsim {

// Sized and read in one call: copying through `stream << rdbuf()` grew the string in steps and
// took 2 ms of a warm liver_probe set-up for its 2.7 MB of cached results (issue 17).
std::string read_text_if_any(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  const std::streamoff size = in.seekg(0, std::ios::end) ? std::streamoff(in.tellg()) : -1;
  if (size < 0) {  // not seekable (a pipe): read as it comes, nothing was consumed
    in.clear();
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.seekg(0);
  in.read(bytes.data(), size);
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  return bytes;
}

}  // namespace mrsim
