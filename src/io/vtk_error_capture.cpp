#include "io/vtk_error_capture.hpp"

#include <vtkCommand.h>
#include <vtkErrorCode.h>
#include <vtkOutputWindow.h>

#include <algorithm>
#include <cstring>
#include <regex>

namespace mrsim {
namespace {

// VTK's text is "ERROR: In <source file>, line N\n<Class> (0x...): <message>\n\n": keep
// "<Class>: <message>", which is what a user can act on.
std::string essential(const std::string& text) {
  const std::size_t body = text.find('\n');
  std::string message = body == std::string::npos ? text : text.substr(body + 1);
  message = message.substr(0, message.find('\n'));
  static const std::regex address(R"( \(0x[0-9a-fA-F]+\))");
  return std::regex_replace(message, address, "");
}

// Pipeline executives add "returned failure for request" after the real error: noise.
bool is_echo(const std::string& message) {
  return message.find("returned failure for request") != std::string::npos;
}

}  // namespace

VtkErrorCapture::VtkErrorCapture()
    : callback_(vtkSmartPointer<vtkCallbackCommand>::New()),
      saved_stderr_verbosity_(vtkLogger::GetCurrentVerbosityCutoff()) {
  callback_->SetCallback(&VtkErrorCapture::on_error);
  callback_->SetClientData(this);
  // Every vtkErrorMacro of an object without its own observer reaches the output window,
  // which raises ErrorEvent; the console copy comes from vtkLogger, silenced meanwhile.
  tag_ = vtkOutputWindow::GetInstance()->AddObserver(vtkCommand::ErrorEvent, callback_);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

VtkErrorCapture::~VtkErrorCapture() {
  vtkLogger::SetStderrVerbosity(saved_stderr_verbosity_);
  vtkOutputWindow::GetInstance()->RemoveObserver(tag_);
}

std::string VtkErrorCapture::summary() const {
  // The first messages carry the cause; the rest repeat it for every block written after.
  constexpr std::size_t kShown = 3;
  std::string joined;
  for (std::size_t i = 0; i < messages_.size() && i < kShown; ++i) {
    if (!joined.empty()) joined += "; ";
    joined += messages_[i];
  }
  if (messages_.size() > kShown) {
    joined += " (and " + std::to_string(messages_.size() - kShown) + " more)";
  }
  return joined;
}

void VtkErrorCapture::on_error(vtkObject*, unsigned long, void* self, void* text) {
  auto* capture = static_cast<VtkErrorCapture*>(self);
  const std::string message =
      essential(text != nullptr ? static_cast<const char*>(text) : "unknown VTK error");
  if (is_echo(message)) return;
  auto& messages = capture->messages_;
  // Each block's writer repeats the same failure: report it once.
  if (std::find(messages.begin(), messages.end(), message) == messages.end()) {
    messages.push_back(message);
  }
}

std::string vtk_error_code_text(unsigned long code) {
  if (code > 0 && code < vtkErrorCode::FirstVTKErrorCode)
    return std::string(std::strerror(static_cast<int>(code))) + " (errno " +
           std::to_string(code) + ")";
  switch (code) {
    case vtkErrorCode::CannotOpenFileError: return "cannot open the file";
    case vtkErrorCode::OutOfDiskSpaceError: return "out of disk space";
    case vtkErrorCode::NoFileNameError: return "no file name";
    default: return "VTK error code " + std::to_string(code);
  }
}

}  // namespace mrsim
