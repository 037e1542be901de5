#include "core/text_file.hpp"

#include <fstream>
#include <sstream>

namespace mrsim {

std::string read_text_if_any(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace mrsim
