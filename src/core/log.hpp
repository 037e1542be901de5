#pragma once
// Warnings go to stderr; --quiet silences them along with progress.
#include <string_view>

namespace mrsim {
void set_quiet(bool quiet);
bool is_quiet();
void warn(std::string_view message);
void info(std::string_view message);
}  // namespace mrsim
