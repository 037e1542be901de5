#pragma once
// A file's whole content written in place through its open descriptor: the frames' files
// reused from the run before (io/file_recycler.hpp) and the .pvd's spare (io/swapped_file.hpp).
#include <string_view>

namespace mrsim {

/// Writes `bytes` into the open file `fd` from offset 0, over what it held, cuts the file to their
/// length when it was longer, and closes `fd`. It is never truncated to 0 first: ext4 would then
/// write the data out when the file is closed (auto_da_alloc). Returns 0, or the errno of the
/// first failure (`fd` is closed either way).
int overwrite_and_close(int fd, std::string_view bytes);

}  // namespace mrsim
