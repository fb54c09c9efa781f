#pragma once
// Private to src/render: reading a VTK render window or image back into an RgbImage.
// Never include this from another module (it carries VTK types).
#include <vtkImageData.h>
#include <vtkRenderWindow.h>

#include "render/render_views.h"

namespace maxillo::render {

// VTK's images start at the bottom row; ours start at the top.
RgbImage from_vtk_image(vtkImageData& image);

// The window's back buffer as rendered last (no re-render).
RgbImage grab_window(vtkRenderWindow& window);

}  // namespace maxillo::render
