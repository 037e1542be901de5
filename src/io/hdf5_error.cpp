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

// HDF5's I/O failures read "file write failed: time = Wed Nov 25 ...\n, filename = ..., errno =
// 27, error message = 'File too large', buf = 0x..., ...": keep "file write failed: File too
// large (errno 27)", on one line.
std::string readable(const std::string& description) {
  const std::string tag = "error message = '";
  const auto at = description.find(tag);
  if (at == std::string::npos) return description;
  const auto end = description.find('\'', at + tag.size());
  std::string out = description.substr(0, description.find(':')) + ": " +
                    description.substr(at + tag.size(), end - at - tag.size());
  const auto errno_at = description.find("errno = ");
  if (errno_at != std::string::npos) {
    const auto digits = description.find_first_not_of("0123456789", errno_at + 8);
    out += " (errno " + description.substr(errno_at + 8, digits - errno_at - 8) + ")";
  }
  return out;
}

herr_t collect(unsigned depth, const H5E_error2_t* entry, void* data) {
  auto* text = static_cast<StackText*>(data);
  const std::string description = readable(entry->desc != nullptr ? entry->desc : "");
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
  std::call_once(once, [] {
    // No library shutdown at exit: every handle of ours is closed by its owner, and after a
    // failed write (disk full) HDF5's own atexit pass tried to flush a file it had failed to
    // close and segfaulted (H5_term_library -> H5F__close_cb), so the run exited 139 instead of
    // reporting the error. Must precede any other HDF5 call to take effect.
    H5dont_atexit();
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  });
}

void throw_error(Where where, std::string_view action) {
  std::string message(where.file);
  if (!where.object.empty()) message += ":" + std::string(where.object);
  message += ": cannot " + std::string(action) + ": " + take_error_stack();
  throw RunError(message);
}

}  // namespace mrsim::h5
