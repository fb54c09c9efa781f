#pragma once
// Private to src/render: turns our plain Scene structs into VTK props.
// Never include this from another module (it carries VTK types).
#include <vtkActor.h>
#include <vtkLookupTable.h>
#include <vtkPolyData.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>

#include "render/scene.h"

namespace maxillo::render {

// Points, triangles and area-weighted vertex normals (smooth shading) of a mesh.
vtkSmartPointer<vtkPolyData> to_polydata(const TriangleMesh& mesh);

// 256-entry table for the map over [range_min, range_max]; out-of-range values clamp.
vtkSmartPointer<vtkLookupTable> make_lookup_table(const VertexScalars& scalars);

// An actor for one scene mesh: flat colour or scalars through a lookup table, opacity,
// and a soft specular highlight. Throws Error(BadValue) for a scalar count mismatch.
vtkSmartPointer<vtkActor> make_actor(const SceneMesh& item);

// A vertical colour bar filling its renderer's viewport (the image's right strip), dark text
// for a light background.
vtkSmartPointer<vtkScalarBarActor> make_colour_bar(const VertexScalars& scalars);

}  // namespace maxillo::render
