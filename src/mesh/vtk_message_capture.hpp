#pragma once
// VTK reports most reading errors by printing them (vtkErrorMacro), not by throwing or by a
// return value, and its XML reader then hands back an empty or partial dataset. While alive,
// this guard collects every VTK error and warning instead of letting them reach stderr: the
// ErrorEvent/WarningEvent of watched objects, plus everything sent to the global
// vtkOutputWindow (the XML parser, decompressors and data arrays report there), and keeps
// vtkLogger from echoing them to stderr.
// It swaps process-wide VTK state, so mesh loading must not run concurrently with other VTK
// use (mrsim loads meshes before any simulation or output work starts).
#include <memory>
#include <string>
#include <vector>

class vtkObject;

namespace mrsim {

class VtkMessageCapture {
 public:
  VtkMessageCapture();
  ~VtkMessageCapture();
  VtkMessageCapture(const VtkMessageCapture&) = delete;
  VtkMessageCapture& operator=(const VtkMessageCapture&) = delete;

  /// Routes `object`'s ErrorEvent and WarningEvent here.
  void watch(vtkObject* object);
  /// Error messages, cleaned of VTK's "ERROR: In file, line" decoration.
  const std::vector<std::string>& errors() const;
  const std::vector<std::string>& warnings() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace mrsim
