#include "io/vtk_level_grid.hpp"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSignedCharArray.h>

#include "io/vtk_arrays.hpp"
#include "io/vtk_tetra_cells.hpp"

namespace mrsim {
namespace {

void add_point_arrays(vtkPointData* data, const LevelFrameView& view) {
  data->AddArray(vector_array("displacement", view.displacement));
  data->AddArray(vector_array("velocity", view.velocity));
  data->AddArray(vector_array("force", view.force));
  data->AddArray(scalar_array<vtkSignedCharArray>("status", view.status));  // Int8 in XML
  data->AddArray(scalar_array<vtkIntArray>("time_level", view.time_level));
  data->AddArray(scalar_array<vtkDoubleArray>("criterion", view.criterion));
  data->AddArray(scalar_array<vtkDoubleArray>("mass", view.mass));
  // Displacement is the default vector so glyphs and Warp By Vector pick it without clicks.
  data->SetActiveVectors("displacement");
}

// Points, point and cell arrays and the time of a frame, on a grid that already has its cells.
void fill_level_grid(vtkUnstructuredGrid* grid, const LevelFrameView& view, double time) {
  grid->SetPoints(deformed_points(view.mesh->points, view.displacement));
  grid->GetPointData()->Initialize();
  add_point_arrays(grid->GetPointData(), view);
  // What the level simulates of each tet: a Threshold `simulated` >= 0.5 on every level block
  // shows the object once, each part on its level (docs/output.md "ParaView").
  grid->GetCellData()->Initialize();
  if (!view.simulated.empty())
    grid->GetCellData()->AddArray(scalar_array<vtkDoubleArray>("simulated", view.simulated));
  if (!view.simulated_by.empty())
    grid->GetCellData()->AddArray(
        scalar_array<vtkSignedCharArray>("simulated_by", view.simulated_by));
  if (!view.calibration_scale.empty()) {
    static const char* const kNames[7] = {"lambda", "xx", "yy", "zz", "yz", "xz", "xy"};
    grid->GetCellData()->AddArray(tuple_array("calibration_scale", view.calibration_scale, kNames));
  }
  grid->GetFieldData()->Initialize();
  add_time_value(grid->GetFieldData(), time);
}

}  // namespace

vtkSmartPointer<vtkUnstructuredGrid> make_level_grid(const LevelFrameView& view, double time) {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetCells(VTK_TETRA, tetra_cells(*view.mesh));
  fill_level_grid(grid, view, time);
  return grid;
}

vtkUnstructuredGrid* LevelGrids::update(std::size_t level, const LevelFrameView& view,
                                        double time) {
  if (kept_.size() <= level) kept_.resize(level + 1);
  Kept& kept = kept_[level];
  if (kept.mesh != view.mesh || kept.points != view.mesh->points.size() ||
      kept.tets != view.mesh->tets.size() || !kept.grid) {
    kept = {view.mesh, view.mesh->points.size(), view.mesh->tets.size(),
            make_level_grid(view, time)};
    return kept.grid;
  }
  fill_level_grid(kept.grid, view, time);
  return kept.grid;
}

}  // namespace mrsim
