#include "io/hdf5_error.hpp"

#include <mutex>
#include <string>

#include "core/error.hpp"

namespace mrsim::h5 {
namespace {

struct StackText {
  std::string outermost;  // what the API call failed to do
  std::string innermost;  // the root cause (often carries errno text)
};

herr_t collect(unsigned depth, const H5E_error2_t* entry, void* data) {
  auto* text = static_cast<StackText*>(data);
  const std::string description = entry->desc != nullptr ? entry->desc : "";
  if (depth == 0) text->outermost = description;
  text->innermost = description;
  return 0;
}

std::string take_error_stack() {
  StackText text;
  // Walking downward visits the API-level entry first and the root cause last.
  if (H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, &collect, &text) < 0) return "unknown HDF5 error";
  H5Eclear2(H5E_DEFAULT);
  if (text.outermost.empty()) return "unknown HDF5 error";
  if (text.innermost == text.outermost) return text.outermost;
  return text.outermost + " (" + text.innermost + ")";
}

}  // namespace

void silence_automatic_error_printing() {
  static std::once_flag once;
  std::call_once(once, [] { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); });
}

void throw_error(Where where, std::string_view action) {
  std::string message(where.file);
  if (!where.object.empty()) message += ":" + std::string(where.object);
  message += ": cannot " + std::string(action) + ": " + take_error_stack();
  throw RunError(message);
}

}  // namespace mrsim::h5
