#include "render/vtk_scene_builder.h"

#include <Eigen/Geometry>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTextProperty.h>

#include <array>
#include <cassert>
#include <string>

#include "core/error.h"

namespace maxillo::render {
namespace {

using Rgb = std::array<double, 3>;

// Moreland's cool-warm diverging map and viridis, as a few control points.
const std::vector<Rgb> kDivergingStops = {{0.230, 0.299, 0.754}, {0.865, 0.865, 0.865}, {0.706, 0.016, 0.150}};
const std::vector<Rgb> kSequentialStops = {
    {0.267, 0.005, 0.329}, {0.229, 0.322, 0.546}, {0.128, 0.567, 0.551}, {0.369, 0.789, 0.383}, {0.993, 0.906, 0.144}};

Rgb interpolate(const std::vector<Rgb>& stops, double t) {
  const double position = t * static_cast<double>(stops.size() - 1);
  const auto below = std::min(static_cast<std::size_t>(position), stops.size() - 2);
  const double f = position - static_cast<double>(below);
  Rgb colour{};
  for (int c = 0; c < 3; ++c) colour[c] = (1 - f) * stops[below][c] + f * stops[below + 1][c];
  return colour;
}

vtkSmartPointer<vtkFloatArray> vertex_normals(const TriangleMesh& mesh) {
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> sum = Eigen::MatrixXd::Zero(mesh.vertex_count(), 3);
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f) {
    const auto a = mesh.faces(f, 0), b = mesh.faces(f, 1), c = mesh.faces(f, 2);
    const Eigen::Vector3d pa = mesh.vertices.row(a), pb = mesh.vertices.row(b), pc = mesh.vertices.row(c);
    const Eigen::Vector3d n = (pb - pa).cross(pc - pa);  // |n| = twice the area
    sum.row(a) += n.transpose();
    sum.row(b) += n.transpose();
    sum.row(c) += n.transpose();
  }
  auto normals = vtkSmartPointer<vtkFloatArray>::New();
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(mesh.vertex_count());
  for (Eigen::Index v = 0; v < mesh.vertex_count(); ++v) {
    const double length = sum.row(v).norm();
    Eigen::Vector3d n = length > 0 ? Eigen::Vector3d(sum.row(v).transpose() / length) : Eigen::Vector3d::UnitZ();
    normals->SetTuple3(v, n.x(), n.y(), n.z());
  }
  return normals;
}

}  // namespace

vtkSmartPointer<vtkPolyData> to_polydata(const TriangleMesh& mesh) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(mesh.vertex_count());
  for (Eigen::Index v = 0; v < mesh.vertex_count(); ++v)
    points->SetPoint(v, mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2));

  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(mesh.face_count() + 1);
  connectivity->SetNumberOfValues(3 * mesh.face_count());
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f) {
    offsets->SetValue(f, 3 * f);
    for (int k = 0; k < 3; ++k) {
      const int vertex = mesh.faces(f, k);
      assert(vertex >= 0 && vertex < mesh.vertex_count() && "to_polydata: face index out of range");
      connectivity->SetValue(3 * f + k, vertex);
    }
  }
  offsets->SetValue(mesh.face_count(), 3 * mesh.face_count());
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  triangles->SetData(offsets, connectivity);

  auto polydata = vtkSmartPointer<vtkPolyData>::New();
  polydata->SetPoints(points);
  polydata->SetPolys(triangles);
  polydata->GetPointData()->SetNormals(vertex_normals(mesh));
  return polydata;
}

vtkSmartPointer<vtkLookupTable> make_lookup_table(const VertexScalars& scalars) {
  const auto& stops = scalars.map == ColourMap::Diverging ? kDivergingStops : kSequentialStops;
  constexpr int kEntries = 256;
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(kEntries);
  table->SetTableRange(scalars.range_min, scalars.range_max);
  for (int i = 0; i < kEntries; ++i) {
    const Rgb c = interpolate(stops, i / double(kEntries - 1));
    table->SetTableValue(i, c[0], c[1], c[2], 1.0);
  }
  table->Build();
  return table;
}

vtkSmartPointer<vtkActor> make_actor(const SceneMesh& item) {
  assert(item.mesh && "make_actor: SceneMesh without a mesh");
  auto polydata = to_polydata(*item.mesh);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(polydata);
  mapper->ScalarVisibilityOff();
  if (item.scalars) {
    const auto& scalars = *item.scalars;
    if (static_cast<Eigen::Index>(scalars.values.size()) != item.mesh->vertex_count())
      throw Error(ErrorCode::kBadValue, "vertex scalars",
                  std::to_string(scalars.values.size()) + " values for " + std::to_string(item.mesh->vertex_count()) +
                      " vertices");
    auto values = vtkSmartPointer<vtkDoubleArray>::New();
    values->SetName("scalars");
    values->SetNumberOfValues(static_cast<vtkIdType>(scalars.values.size()));
    for (std::size_t i = 0; i < scalars.values.size(); ++i)
      values->SetValue(static_cast<vtkIdType>(i), scalars.values[i]);
    polydata->GetPointData()->SetScalars(values);
    mapper->SetLookupTable(make_lookup_table(scalars));
    mapper->SetScalarRange(scalars.range_min, scalars.range_max);
    mapper->SetColorModeToMapScalars();
    mapper->ScalarVisibilityOn();
  }
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  auto* property = actor->GetProperty();
  property->SetColor(item.colour.r, item.colour.g, item.colour.b);
  property->SetOpacity(item.opacity);
  property->SetInterpolationToPhong();
  property->SetAmbient(0.08);
  property->SetDiffuse(0.85);
  property->SetSpecular(0.15);
  property->SetSpecularPower(25);
  return actor;
}

vtkSmartPointer<vtkScalarBarActor> make_colour_bar(const VertexScalars& scalars) {
  auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
  bar->SetLookupTable(make_lookup_table(scalars));
  bar->SetTitle(scalars.title.c_str());
  bar->SetNumberOfLabels(5);
  bar->SetLabelFormat("%.1f");
  bar->SetOrientationToVertical();
  // Coordinates are fractions of the bar's own viewport (the image's right strip).
  bar->SetPosition(0.08, 0.12);
  bar->SetPosition2(0.84, 0.76);  // width, height
  bar->SetBarRatio(0.3);
  bar->SetTextPositionToSucceedScalarBar();
  bar->SetVerticalTitleSeparation(8);
  for (auto* text : {bar->GetTitleTextProperty(), bar->GetLabelTextProperty()}) {
    text->SetColor(0.15, 0.15, 0.15);
    text->SetFontFamilyToArial();
    text->BoldOff();
    text->ItalicOff();
    text->ShadowOff();
    text->SetFontSize(16);
  }
  return bar;
}

}  // namespace maxillo::render
