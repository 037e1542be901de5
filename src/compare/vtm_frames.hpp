#pragma once
// One frame of a run's VTK series (frames/frame_NNNNNN.vtm and its .vtu/.vtp pieces), read with
// VTK's multiblock reader and turned into the arrays a comparison needs: per block the points,
// the cells (types and connectivity), and every point, cell and field array. One frame at a
// time: a comparison never holds the whole series.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "compare/value_array.hpp"

namespace mrsim {

struct BlockArray {
  std::string label;  // "points", "cell connectivity", "point array displacement", ...
  AxisNames axes;     // how an index reads: {"point", "component"}
  ValueArray values;
};

struct FrameBlock {
  std::string name;             // "level_0", "surface", "tool"
  std::string type;             // VTK class: "vtkUnstructuredGrid", "vtkPolyData"
  std::filesystem::path piece;  // its file, for messages
  std::size_t points = 0;
  std::size_t cells = 0;
  std::vector<BlockArray> arrays;  // points, cell types, connectivity (offsets when the cells
                                   // differ in size), then point, cell and field arrays
};

/// The blocks of the frame in file order. VTK returns empty data rather than failing, so
/// what it read is checked: every piece listed must exist, a .vtu piece's header must fit its
/// size and VTK must read the counts it declares, and VTK must report no error. Throws
/// InputError naming the .vtm or the piece otherwise.
std::vector<FrameBlock> read_vtm_frame(const std::filesystem::path& vtm);

}  // namespace mrsim
