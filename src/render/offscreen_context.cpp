#include "render/offscreen_context.h"

#include <GL/osmesa.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>

#include <string>

#include "core/error.h"
#include "render/offscreen_context_impl.h"

// GLEW, as built by Debian, finds GL entry points through GLX. With no X display those lookups
// must go to OSMesa instead. Defining these C symbols here overrides libGL's: the linker takes
// the first definition, and our object file comes before libGL (see src/render/CMakeLists.txt).
extern "C" {
using GenericProc = void (*)();
GenericProc glXGetProcAddressARB(const unsigned char* name) {
  return reinterpret_cast<GenericProc>(OSMesaGetProcAddress(reinterpret_cast<const char*>(name)));
}
GenericProc glXGetProcAddress(const unsigned char* name) {
  return reinterpret_cast<GenericProc>(OSMesaGetProcAddress(reinterpret_cast<const char*>(name)));
}
// GLX extensions are meaningless without X: report success without querying a display.
int glxewInit() { return 0; }
}

namespace maxillo::render {
namespace {

OSMesaContext create_core_context() {
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            24,
                            OSMESA_STENCIL_BITS,
                            8,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            2,
                            0};
  OSMesaContext context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!context) throw Error(ErrorCode::kRenderFailed, "OSMesa", "cannot create an OpenGL 3.2 core-profile context");
  return context;
}

// VTK asks the generic window to become current / whether it is current through events.
void on_window_event(vtkObject*, unsigned long event, void* client_data, void* call_data) {
  auto* impl = static_cast<OffscreenContext::Impl*>(client_data);
  if (event == vtkCommand::WindowMakeCurrentEvent) impl->try_make_current();  // no throw through VTK
  if (event == vtkCommand::WindowIsCurrentEvent) *static_cast<bool*>(call_data) = impl->is_current();
  // WindowFrameEvent: nothing to swap, the image is read back from VTK's framebuffer.
}

}  // namespace

bool OffscreenContext::Impl::try_make_current() {
  auto* context = static_cast<OSMesaContext>(osmesa_context);
  return OSMesaMakeCurrent(context, buffer.data(), GL_UNSIGNED_BYTE, size.width, size.height);
}

void OffscreenContext::Impl::make_current() {
  if (!try_make_current())
    throw Error(ErrorCode::kRenderFailed, "OSMesa", "cannot make the off-screen context current");
}

bool OffscreenContext::Impl::is_current() const {
  return OSMesaGetCurrentContext() == static_cast<OSMesaContext>(osmesa_context);
}

OffscreenContext::OffscreenContext(ImageSize size) : impl_(std::make_unique<Impl>()) {
  if (size.width <= 0 || size.height <= 0 || size.width > 8192 || size.height > 8192)
    throw Error(ErrorCode::kBadValue, "image size",
                std::to_string(size.width) + "x" + std::to_string(size.height) + " outside 1..8192 pixels");
  impl_->size = size;
  impl_->buffer.resize(static_cast<std::size_t>(size.width) * size.height * 4);
  impl_->osmesa_context = create_core_context();
  impl_->make_current();

  auto callback = vtkSmartPointer<vtkCallbackCommand>::New();
  callback->SetCallback(on_window_event);
  callback->SetClientData(impl_.get());

  auto& window = impl_->window;
  window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  window->SetOwnContext(false);
  window->SetReadyForRendering(true);
  window->SetIsCurrent(true);
  window->SetSize(size.width, size.height);
  window->SetMultiSamples(0);  // depth peeling (translucent skin) needs a single-sample buffer
  window->SetAlphaBitPlanes(1);
  window->AddObserver(vtkCommand::WindowMakeCurrentEvent, callback);
  window->AddObserver(vtkCommand::WindowIsCurrentEvent, callback);
  window->AddObserver(vtkCommand::WindowFrameEvent, callback);
}

OffscreenContext::~OffscreenContext() {
  if (impl_->window && impl_->try_make_current()) {
    impl_->window->Finalize();  // frees VTK's GL resources while the context still exists
  }
  impl_->window = nullptr;
  OSMesaDestroyContext(static_cast<OSMesaContext>(impl_->osmesa_context));
}

ImageSize OffscreenContext::size() const { return impl_->size; }

}  // namespace maxillo::render
