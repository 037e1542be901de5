#include "mesh/vtk_message_capture.hpp"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkLogger.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>

namespace mrsim {
namespace {

// VTK's text is "ERROR: In /path/file.cxx, line 123\nvtkClass (0x55d...): message\n\n":
// keep only the message.
std::string clean(const char* text) {
  std::string s = text ? text : "";
  const auto header_end = s.find('\n');
  if (s.rfind("ERROR: In ", 0) == 0 || s.rfind("Warning: In ", 0) == 0)
    s = header_end == std::string::npos ? "" : s.substr(header_end + 1);
  const auto address = s.find("): ");
  if (address != std::string::npos && s.find(" (0x") < address) s = s.substr(address + 3);
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

class CaptureWindow : public vtkOutputWindow {
 public:
  static CaptureWindow* New();
  vtkTypeMacro(CaptureWindow, vtkOutputWindow)
  void DisplayText(const char*) override {}
  void DisplayErrorText(const char* text) override { errors.push_back(clean(text)); }
  void DisplayWarningText(const char* text) override { warnings.push_back(clean(text)); }
  void DisplayGenericWarningText(const char* text) override { warnings.push_back(clean(text)); }
  void DisplayDebugText(const char*) override {}

  std::vector<std::string> errors, warnings;
};
vtkStandardNewMacro(CaptureWindow);

void on_event(vtkObject*, unsigned long event, void* client, void* call_data) {
  auto* window = static_cast<CaptureWindow*>(client);
  const std::string text = clean(static_cast<const char*>(call_data));
  (event == vtkCommand::ErrorEvent ? window->errors : window->warnings).push_back(text);
}

}  // namespace

struct VtkMessageCapture::State {
  vtkSmartPointer<vtkOutputWindow> previous;
  vtkSmartPointer<CaptureWindow> window;
  vtkSmartPointer<vtkCallbackCommand> callback;
  int previous_display = 1;
  vtkLogger::Verbosity previous_stderr = vtkLogger::VERBOSITY_INFO;
};

VtkMessageCapture::VtkMessageCapture() : state_(std::make_unique<State>()) {
  state_->previous = vtkOutputWindow::GetInstance();
  state_->window = vtkSmartPointer<CaptureWindow>::New();
  vtkOutputWindow::SetInstance(state_->window);
  // With the global display off (a quiet caller), VTK would not even raise ErrorEvent.
  state_->previous_display = vtkObject::GetGlobalWarningDisplay();
  vtkObject::GlobalWarningDisplayOn();
  // Errors of unobserved objects are also logged to stderr by vtkLogger: silence it. VTK has
  // no getter for the stderr level; the cutoff equals it unless log files were added.
  state_->previous_stderr = vtkLogger::GetCurrentVerbosityCutoff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  state_->callback = vtkSmartPointer<vtkCallbackCommand>::New();
  state_->callback->SetCallback(on_event);
  state_->callback->SetClientData(state_->window.Get());
}

VtkMessageCapture::~VtkMessageCapture() {
  vtkLogger::SetStderrVerbosity(state_->previous_stderr);
  vtkObject::SetGlobalWarningDisplay(state_->previous_display);
  vtkOutputWindow::SetInstance(state_->previous);
}

void VtkMessageCapture::watch(vtkObject* object) {
  object->AddObserver(vtkCommand::ErrorEvent, state_->callback);
  object->AddObserver(vtkCommand::WarningEvent, state_->callback);
}

const std::vector<std::string>& VtkMessageCapture::errors() const { return state_->window->errors; }
const std::vector<std::string>& VtkMessageCapture::warnings() const { return state_->window->warnings; }

}  // namespace mrsim
