// TriangleMesh <-> vtkPolyData.
#include "mesh/vtk_bridge.h"

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkPoints.h>

#include <vector>

namespace maxillo::vtk_bridge {

vtkSmartPointer<vtkPolyData> to_polydata(const TriangleMesh& mesh) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(mesh.vertex_count());
  for (Eigen::Index v = 0; v < mesh.vertex_count(); ++v)
    points->SetPoint(v, mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2));
  vtkNew<vtkCellArray> triangles;
  triangles->AllocateExact(mesh.face_count(), mesh.face_count() * 3);
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f) {
    vtkIdType ids[3] = {mesh.faces(f, 0), mesh.faces(f, 1), mesh.faces(f, 2)};
    triangles->InsertNextCell(3, ids);
  }
  auto polydata = vtkSmartPointer<vtkPolyData>::New();
  polydata->SetPoints(points);
  polydata->SetPolys(triangles);
  return polydata;
}

TriangleMesh from_polydata(vtkPolyData* polydata) {
  TriangleMesh mesh;
  const vtkIdType point_count = polydata->GetNumberOfPoints();
  mesh.vertices.resize(point_count, 3);
  for (vtkIdType v = 0; v < point_count; ++v) {
    double p[3];
    polydata->GetPoint(v, p);
    mesh.vertices.row(v) << p[0], p[1], p[2];
  }
  std::vector<Eigen::Vector3i> faces;
  faces.reserve(size_t(polydata->GetNumberOfPolys()));
  vtkCellArray* polys = polydata->GetPolys();
  vtkNew<vtkIdList> ids;
  for (polys->InitTraversal(); polys->GetNextCell(ids);)
    for (vtkIdType c = 1; c + 1 < ids->GetNumberOfIds(); ++c)
      faces.emplace_back(int(ids->GetId(0)), int(ids->GetId(c)), int(ids->GetId(c + 1)));
  vtkCellArray* strips = polydata->GetStrips();
  for (strips->InitTraversal(); strips->GetNextCell(ids);)
    for (vtkIdType c = 0; c + 2 < ids->GetNumberOfIds(); ++c) {
      int a = int(ids->GetId(c)), b = int(ids->GetId(c + 1)), d = int(ids->GetId(c + 2));
      if (c % 2) std::swap(a, b);  // strips alternate their winding
      faces.emplace_back(a, b, d);
    }
  mesh.faces.resize(Eigen::Index(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f) mesh.faces.row(Eigen::Index(f)) = faces[f].transpose();
  return mesh;
}

void ErrorCollector::Execute(vtkObject*, unsigned long event, void* data) {
  if (event != vtkCommand::ErrorEvent) return;  // warnings are swallowed, errors recorded
  if (!errors.empty()) errors += "; ";
  std::string text = data ? static_cast<const char*>(data) : "unknown VTK error";
  // VTK prefixes "ERROR: In <source file>, line N\n<class> (<address>): "; keep the message.
  if (auto cut = text.rfind("): "); cut != std::string::npos) text = text.substr(cut + 3);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  errors += text;
}

void ErrorCollector::observe(vtkObject* object) {
  object->AddObserver(vtkCommand::ErrorEvent, this);
  object->AddObserver(vtkCommand::WarningEvent, this);
}

}  // namespace maxillo::vtk_bridge
