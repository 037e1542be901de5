// The entry points of libmrsim_vtk.so (core/vtk_module.hpp): the only symbol it exports; the
// rest of it is built with hidden visibility, so its functions never bind to the executable's.
#include <memory>

#include "compare/vtk_xml_index.hpp"
#include "compare/vtm_frames.hpp"
#include "core/vtk_module.hpp"
#include "io/vtk_series_writer.hpp"
#include "mesh/vtu_reader.hpp"
#include "mrsim/version.hpp"

namespace mrsim {
namespace {

std::unique_ptr<FrameSeriesWriter> series_writer(const std::filesystem::path& out_dir,
                                                 FrameCompression compression) {
  return std::make_unique<VtkSeriesWriter>(out_dir, compression);
}

constexpr VtkEntryPoints kEntryPoints{sizeof(VtkEntryPoints), kGitRevision, &read_vtu,
                                      &series_writer, &read_dataset_entries, &read_vtm_frame};

}  // namespace
}  // namespace mrsim

extern "C" __attribute__((visibility("default"))) const mrsim::VtkEntryPoints*
mrsim_vtk_entry_points() {
  return &mrsim::kEntryPoints;
}
