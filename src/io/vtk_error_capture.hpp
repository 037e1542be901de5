#pragma once
// VTK never throws: it logs errors to stderr (through vtkLogger) and sets error codes. While one
// of these is alive, every VTK error, including those of the inner writers and pipeline
// executives a composite writer creates, is captured here instead of printed, so the caller
// can throw one RunError carrying VTK's own diagnosis (e.g. "Not a directory").
// Scoped to one write on the calling thread; VTK's logging state is restored afterwards.
#include <string>
#include <vector>

#include <vtkCallbackCommand.h>
#include <vtkLogger.h>
#include <vtkSmartPointer.h>

namespace mrsim {

/// A writer's error code in words: codes below vtkErrorCode::FirstVTKErrorCode are the system's
/// errno ("No space left on device (errno 28)"), the others VTK's own (vtkErrorCode's text
/// lives in CommonMisc, which mrsim does not link).
std::string vtk_error_code_text(unsigned long code);

class VtkErrorCapture {
 public:
  VtkErrorCapture();
  ~VtkErrorCapture();
  VtkErrorCapture(const VtkErrorCapture&) = delete;
  VtkErrorCapture& operator=(const VtkErrorCapture&) = delete;

  bool any() const { return !messages_.empty(); }
  /// The distinct messages, without VTK's source-file lines and object addresses, "; "-joined.
  std::string summary() const;

 private:
  static void on_error(vtkObject* caller, unsigned long event, void* self, void* message);
  vtkSmartPointer<vtkCallbackCommand> callback_;
  unsigned long tag_ = 0;
  vtkLogger::Verbosity saved_stderr_verbosity_;
  std::vector<std::string> messages_;
};

}  // namespace mrsim
