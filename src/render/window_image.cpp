#include "render/window_image.h"

#include <vtkSmartPointer.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>

namespace maxillo::render {

RgbImage from_vtk_image(vtkImageData& image) {
  int dimensions[3];
  image.GetDimensions(dimensions);
  const int components = image.GetNumberOfScalarComponents();
  RgbImage out{dimensions[0], dimensions[1], {}};
  out.pixels.resize(static_cast<std::size_t>(out.width) * out.height * 3);
  const auto* source = static_cast<const std::uint8_t*>(image.GetScalarPointer());
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      const std::uint8_t* in = source + (static_cast<std::size_t>(out.height - 1 - y) * out.width + x) * components;
      std::uint8_t* px = &out.pixels[(static_cast<std::size_t>(y) * out.width + x) * 3];
      for (int c = 0; c < 3; ++c) px[c] = in[std::min(c, components - 1)];
    }
  return out;
}

RgbImage grab_window(vtkRenderWindow& window) {
  auto grabber = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grabber->SetInput(&window);
  grabber->SetInputBufferTypeToRGB();
  grabber->ReadFrontBufferOff();
  grabber->ShouldRerenderOff();
  grabber->Update();
  return from_vtk_image(*grabber->GetOutput());
}

}  // namespace maxillo::render
