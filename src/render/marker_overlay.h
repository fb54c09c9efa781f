#pragma once
// Private to src/render: the props that draw a scene's markers (render/scene.h) over a rendered
// view: discs, labels placed by render/label_layout.h, and the leader lines of labels that had
// to move away. Never include this from another module (it carries VTK types).
#include <vtkProp.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <span>
#include <vector>

#include "render/scene.h"

namespace maxillo::render {

// The props for `markers` seen through the renderer's current camera (applied, with the window
// at its final size). Markers behind the camera or outside the viewport are left out.
std::vector<vtkSmartPointer<vtkProp>> marker_props(vtkRenderer& renderer, std::span<const SceneMarker> markers);

}  // namespace maxillo::render
