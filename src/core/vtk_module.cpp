#include "core/vtk_module.hpp"

#include <dlfcn.h>

#include <cstring>
#include <string>
#include <string_view>
#include <system_error>

#include "core/error.hpp"
#include "mrsim/version.hpp"

// Defined by VTK's part (io/vtk_module_entry.cpp). Weak: a program without that part links, and
// loads the library instead.
extern "C" const mrsim::VtkEntryPoints* mrsim_vtk_entry_points() __attribute__((weak));

namespace mrsim {

namespace {

constexpr const char* kLibrary = "libmrsim_vtk.so";

std::filesystem::path library_path() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path(kLibrary) : exe.parent_path() / kLibrary;
}

const VtkEntryPoints* load() {
  if (mrsim_vtk_entry_points != nullptr) return mrsim_vtk_entry_points();  // linked in
  const std::filesystem::path path = library_path();
  // RTLD_NOW: a symbol the executable does not export is said here, not at some later call.
  void* library = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) {
    const char* why = ::dlerror();
    throw RunError("cannot load " + path.string() +
                   " (mrsim's VTK readers and writers, built beside mrsim by scripts/build.sh): " +
                   (why ? why : "unknown reason"));
  }
  void* entry = ::dlsym(library, "mrsim_vtk_entry_points");
  if (entry == nullptr)
    throw RunError(path.string() + " is not mrsim's VTK library: no mrsim_vtk_entry_points");
  const VtkEntryPoints* (*entry_points)();
  static_assert(sizeof entry_points == sizeof entry);
  std::memcpy(&entry_points, &entry, sizeof entry);  // POSIX: a function's address as void*
  const VtkEntryPoints* e = entry_points();  // the library stays loaded until the process ends
  check_vtk_entry_points(*e, path);
  return e;
}

}  // namespace

const VtkEntryPoints& vtk_module() {
  static const VtkEntryPoints* const entry = load();  // a failed load is tried again next time
  return *entry;
}

void check_vtk_entry_points(const VtkEntryPoints& e, const std::filesystem::path& library) {
  // The size first: a table of another layout may not even hold a revision where this one does.
  if (e.size != sizeof(VtkEntryPoints))
    throw RunError(library.string() + " is from another build of mrsim (its entry table has " +
                   std::to_string(e.size) + " bytes, not " +
                   std::to_string(sizeof(VtkEntryPoints)) + "): rebuild with scripts/build.sh");
  if (e.git_revision == nullptr || std::string_view(e.git_revision) != kGitRevision)
    throw RunError(library.string() + " was built from revision " +
                   (e.git_revision ? e.git_revision : "?") + ", this mrsim from " +
                   kGitRevision + ": rebuild both with scripts/build.sh");
}

}  // namespace mrsim
