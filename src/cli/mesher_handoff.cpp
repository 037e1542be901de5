#include "cli/mesher_handoff.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace mrsim {

int hand_over_to_mesher(int argc, char** argv, int first) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  const fs::path mesher = (ec ? fs::path(argv[0]) : self).parent_path() / kMesherProgram;
  std::string name = "mrsim mesh";
  std::vector<char*> args{name.data()};
  for (int i = first; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  ::execv(mesher.c_str(), args.data());
  const int err = errno;
  std::cerr << "error: mrsim mesh runs " << mesher.string() << ", which cannot be started ("
            << std::strerror(err) << "): build it beside mrsim (cmake --build build --target "
            << kMesherProgram << ", or scripts/build.sh)\n";
  return kExitRunFailure;
}

}  // namespace mrsim
