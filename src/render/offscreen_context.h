#pragma once
// An off-screen OpenGL context for rendering without any display (no X, no Xvfb).
//
// Debian's VTK is built for X/GLX, not for OSMesa. We create an OSMesa core-profile (3.2)
// context ourselves on our own RGBA buffer, make it current, and hand VTK a
// vtkGenericOpenGLRenderWindow that renders into it. GLEW (which VTK uses to load GL entry
// points) is redirected to OSMesaGetProcAddress by symbols defined in offscreen_context.cpp.
//
// RAII: the constructor makes the context current on the calling thread; the destructor
// releases the VTK window and destroys the context. One context at a time per thread; the
// object is neither copyable nor movable (VTK observers hold its address).
#include <memory>

namespace maxillo::render {

struct ImageSize {
  int width = 1024;   // pixels
  int height = 1024;  // pixels
};

class OffscreenContext {
 public:
  // Throws Error(RenderFailed) when OSMesa cannot create a core-profile context.
  explicit OffscreenContext(ImageSize size);
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  ImageSize size() const;

  // The VTK side (render window) lives in offscreen_context_impl.h, included only by the
  // render module's own .cpp files.
  struct Impl;
  Impl& impl() { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace maxillo::render
