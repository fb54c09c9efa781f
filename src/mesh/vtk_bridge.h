#pragma once
// Internal to src/mesh: conversions between TriangleMesh and vtkPolyData, and an observer that
// turns VTK's error events into text we can put into an Error. Never include from another module.
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <string>

#include "core/triangle_mesh.h"

class vtkObject;

namespace maxillo::vtk_bridge {

vtkSmartPointer<vtkPolyData> to_polydata(const TriangleMesh& mesh);
// Triangles only: polygons with more corners are fan-triangulated, lines and vertices ignored.
TriangleMesh from_polydata(vtkPolyData* polydata);

// Collects ErrorEvent/WarningEvent messages of the objects it observes (and keeps VTK from
// printing them on standard error).
class ErrorCollector : public vtkCommand {
 public:
  static ErrorCollector* New() { return new ErrorCollector; }
  void Execute(vtkObject*, unsigned long event, void* data) override;
  void observe(vtkObject* object);
  bool failed() const { return !errors.empty(); }
  std::string errors;
};

}  // namespace maxillo::vtk_bridge
