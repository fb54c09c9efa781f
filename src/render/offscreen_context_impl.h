#pragma once
// Private to src/render: the VTK render window behind an OffscreenContext.
// Never include this from another module (it carries VTK types).
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkSmartPointer.h>

#include <vector>

#include "render/offscreen_context.h"

namespace maxillo::render {

struct OffscreenContext::Impl {
  ImageSize size;
  void* osmesa_context = nullptr;     // OSMesaContext (kept opaque here)
  std::vector<unsigned char> buffer;  // RGBA colour buffer OSMesa draws into
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> window;

  bool try_make_current();
  void make_current();  // throws Error(RenderFailed)
  bool is_current() const;
};

}  // namespace maxillo::render
