#pragma once
// Checks what a .vtu file declares (NumberOfPoints/NumberOfCells of each Piece, the components,
// offsets and compressed block headers of every element VTK may read as an array, whatever its
// tag name, spacing or format attribute) against the size of the file, before
// VTK is given the file. VTK trusts these numbers: a lying block count makes it allocate and clear
// gigabytes, and a lying point count makes it allocate the arrays, even though the data is not
// there.
#include <cstdint>
#include <filesystem>
#include <string>

namespace mrsim {

struct VtuDeclared {
  std::int64_t points = 0;  // summed over pieces
  std::int64_t cells = 0;
};

/// Throws InputError (naming `path`) if the file is not a VTK XML UnstructuredGrid file or
/// declares more than its bytes can hold.
VtuDeclared check_vtu_header(const std::string& bytes, const std::filesystem::path& path);

}  // namespace mrsim
