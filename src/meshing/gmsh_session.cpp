#include "meshing/gmsh_session.hpp"

#include <fcntl.h>
#include <gmsh.h>
#include <unistd.h>

#include <cstdio>

namespace mrsim {
namespace {

class GmshProcess {
 public:
  GmshProcess() {
    // No config files: the user's ~/.gmshrc must not change mrsim's meshes.
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.AbortOnError", 0);
    gmsh::option::setNumber("General.Verbosity", 2);  // errors and warnings reach the logger
  }
  ~GmshProcess() { gmsh::finalize(); }
  GmshProcess(const GmshProcess&) = delete;
  GmshProcess& operator=(const GmshProcess&) = delete;
};

void ensure_initialised() {
  static GmshProcess process;  // once per process, finalised at exit
}

std::vector<std::string> take_log() {
  std::vector<std::string> log;
  gmsh::logger::get(log);
  gmsh::logger::stop();
  gmsh::logger::start();
  return log;
}

}  // namespace

GmshModel::GmshModel(const std::string& name) {
  ensure_initialised();
  gmsh::clear();
  gmsh::model::add(name);
  gmsh::logger::start();
  take_log();  // drop anything logged before this unit of work
}

GmshModel::~GmshModel() {
  gmsh::logger::stop();
  gmsh::clear();
}

void GmshModel::throw_on_errors(const std::string& what) {
  std::string errors;
  for (const std::string& line : take_log()) {
    if (line.rfind("Error", 0) != 0) continue;
    std::string message = line.substr(line.find(':') + 1);
    while (!message.empty() && (message.front() == ' ')) message.erase(0, 1);
    while (!message.empty() && (message.back() == ' ' || message.back() == '\n')) message.pop_back();
    if (errors.find(message) != std::string::npos) continue;
    errors += (errors.empty() ? "" : "; ") + message;
  }
  if (!errors.empty()) throw GmshFailure(what + ": " + errors);
}

SilencedOutput::SilencedOutput() {
  std::fflush(stdout);
  std::fflush(stderr);
  const int null = ::open("/dev/null", O_WRONLY);
  if (null < 0) return;  // nothing to silence with: gmsh's chatter stays visible
  saved_out_ = ::dup(1);
  saved_err_ = ::dup(2);
  ::dup2(null, 1);
  ::dup2(null, 2);
  ::close(null);
}

SilencedOutput::~SilencedOutput() {
  std::fflush(stdout);
  std::fflush(stderr);
  if (saved_out_ >= 0) ::dup2(saved_out_, 1), ::close(saved_out_);
  if (saved_err_ >= 0) ::dup2(saved_err_, 2), ::close(saved_err_);
}

}  // namespace mrsim
