// Iso-surface extraction with VTK. VTK 9.1 filters ignore vtkImageData's direction matrix, so
// the surface is computed in index*spacing space and mapped to LPS here (origin + direction*p).
#include "mesh/surface_extraction.h"

#include <vtkDecimatePro.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkShortArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowedSincPolyDataFilter.h>

#include <cassert>
#include <limits>

#include "mesh/mesh_measures.h"
#include "mesh/mesh_repair.h"
#include "mesh/vtk_bridge.h"

namespace maxillo {
namespace {

// vtkImageData of size+2 in each axis: the volume surrounded by one voxel of `outside`, placed
// so that point (i+1, j+1, k+1) of the image sits at spacing.*(i, j, k).
template <typename Value, typename Array>
vtkSmartPointer<vtkImageData> padded_image(const VolumeGeometry& g, Value outside, auto value_at) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  const int nx = g.size.x() + 2, ny = g.size.y() + 2, nz = g.size.z() + 2;
  image->SetDimensions(nx, ny, nz);
  image->SetSpacing(g.spacing.x(), g.spacing.y(), g.spacing.z());
  image->SetOrigin(-g.spacing.x(), -g.spacing.y(), -g.spacing.z());
  vtkNew<Array> values;
  values->SetNumberOfTuples(vtkIdType(nx) * ny * nz);
  Value* out = values->GetPointer(0);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        bool inside = i > 0 && j > 0 && k > 0 && i < nx - 1 && j < ny - 1 && k < nz - 1;
        *out++ = inside ? value_at(g.index(i - 1, j - 1, k - 1)) : outside;
      }
  image->GetPointData()->SetScalars(values);
  return image;
}

TriangleMesh flying_edges(vtkImageData* image, double iso) {
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(image);
  contour->SetValue(0, iso);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  return vtk_bridge::from_polydata(contour->GetOutput());
}

TriangleMesh smooth_and_decimate(const TriangleMesh& mesh, const SurfaceOptions& options) {
  vtkSmartPointer<vtkPolyData> current = vtk_bridge::to_polydata(mesh);
  vtkNew<vtkWindowedSincPolyDataFilter> smoother;
  if (options.smoothing_iterations > 0) {
    smoother->SetInputData(current);
    smoother->SetNumberOfIterations(options.smoothing_iterations);
    smoother->SetPassBand(options.smoothing_passband);
    smoother->BoundarySmoothingOff();
    smoother->FeatureEdgeSmoothingOff();
    smoother->NonManifoldSmoothingOn();
    smoother->NormalizeCoordinatesOn();
    smoother->Update();
    current = smoother->GetOutput();
  }
  // vtkQuadricDecimation gives nicer triangles but left 12 boundary and 31 non-manifold edges
  // on the cadaver skin; vtkDecimatePro with PreserveTopology leaves a handful of fins and
  // pinches, which finish_surface repairs.
  vtkNew<vtkDecimatePro> decimator;
  if (options.target_triangles > 0 && mesh.face_count() > options.target_triangles) {
    decimator->SetInputData(current);
    decimator->SetTargetReduction(1.0 - double(options.target_triangles) / double(mesh.face_count()));
    decimator->PreserveTopologyOn();
    decimator->SplittingOff();
    decimator->BoundaryVertexDeletionOff();
    decimator->SetMaximumError(VTK_DOUBLE_MAX);
    decimator->SetFeatureAngle(60);
    decimator->Update();
    current = decimator->GetOutput();
  }
  return vtk_bridge::from_polydata(current);
}

TriangleMesh finish_surface(vtkImageData* image, double iso, const VolumeGeometry& g, const SurfaceOptions& options) {
  TriangleMesh mesh = flying_edges(image, iso);
  if (mesh.face_count() == 0) return mesh;
  mesh = keep_largest_components(mesh, options.keep_largest_components, options.min_component_fraction);
  mesh = smooth_and_decimate(mesh, options);
  // Decimation may leave double-sided fins, small holes and pinched edges (a few per head-sized
  // surface): remove the fins, close the holes they open, unpinch, and drop any piece this
  // separated, so the result stays closed and manifold.
  int64_t changes = remove_duplicate_faces(mesh);
  for (int round = 0; round < 3 && !is_watertight(mesh); ++round) {
    changes += split_pinched_vertices(mesh);  // may open holes where an edge had 3 faces ...
    changes += close_small_holes(mesh);       // ... which are closed here
  }
  if (changes > 0) mesh = keep_largest_components(mesh, options.keep_largest_components, options.min_component_fraction);
  // index*spacing space -> LPS. A left-handed direction matrix mirrors the mesh; orient_outward
  // repairs the winding afterwards.
  for (Eigen::Index v = 0; v < mesh.vertex_count(); ++v)
    mesh.vertices.row(v) = (g.origin + g.direction * mesh.vertices.row(v).transpose()).transpose();
  orient_outward(mesh);
  return mesh;
}

}  // namespace

TriangleMesh extract_surface(const Volume& volume, double iso_hu, const SurfaceOptions& options) {
  const VolumeGeometry& g = volume.geometry;
  assert(volume.hu.size() == size_t(g.voxel_count()) && "volume.hu must hold size.x*size.y*size.z values");
  assert(iso_hu > std::numeric_limits<int16_t>::min() && "iso_hu must be above the padding value");
  auto image = padded_image<int16_t, vtkShortArray>(g, std::numeric_limits<int16_t>::min(),
                                                    [&](int64_t n) { return volume.hu[size_t(n)]; });
  return finish_surface(image, iso_hu, g, options);
}

TriangleMesh extract_surface(const LabelVolume& mask, uint8_t label, const SurfaceOptions& options) {
  const VolumeGeometry& g = mask.geometry;
  assert(mask.labels.size() == size_t(g.voxel_count()) && "mask.labels must hold size.x*size.y*size.z values");
  auto image = padded_image<uint8_t, vtkUnsignedCharArray>(
      g, uint8_t(0), [&](int64_t n) { return uint8_t(mask.labels[size_t(n)] == label ? 1 : 0); });
  return finish_surface(image, 0.5, g, options);
}

}  // namespace maxillo
