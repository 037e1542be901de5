#pragma once
// gmsh's C++ API is a process-wide singleton that must be initialised once before use and
// finalised once at the end. GmshModel is the scoped unit of work on top of it: it makes sure
// the API is initialised (once per process; finalised at exit), opens a fresh model, captures
// gmsh's messages instead of printing them, and removes the model again.
//
// gmsh is configured not to throw (General.AbortOnError = 0): an exception thrown from inside
// gmsh 4.8's mesher leaves its global "busy" lock set, after which every later generate()
// silently does nothing. Errors are read back from gmsh's logger instead (throw_on_errors).
#include <stdexcept>
#include <string>
#include <vector>

namespace mrsim {

/// gmsh reported an error: one meshing attempt failed (callers may try other settings).
struct GmshFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class GmshModel {
 public:
  explicit GmshModel(const std::string& name);
  ~GmshModel();
  GmshModel(const GmshModel&) = delete;
  GmshModel& operator=(const GmshModel&) = delete;

  /// Throws GmshFailure("<what>: <gmsh's error lines>") if gmsh logged an error since the
  /// model was opened or since the last call.
  void throw_on_errors(const std::string& what);
};

}  // namespace mrsim

namespace mrsim {

/// Parts of gmsh 4.8 (the Delaunay boundary recovery) print to stdout with printf, whatever
/// General.Terminal says. While one of these lives, file descriptors 1 and 2 point to
/// /dev/null, so `mrsim mesh` keeps its output clean; gmsh's errors still reach its logger.
class SilencedOutput {
 public:
  SilencedOutput();
  ~SilencedOutput();
  SilencedOutput(const SilencedOutput&) = delete;
  SilencedOutput& operator=(const SilencedOutput&) = delete;

 private:
  int saved_out_ = -1;
  int saved_err_ = -1;
};

}  // namespace mrsim
