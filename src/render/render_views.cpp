#include "render/render_views.h"

#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkLightKit.h>
#include <vtkMath.h>
#include <vtkRendererCollection.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

#include "core/atomic_file.h"
#include "core/error.h"
#include "render/marker_overlay.h"
#include "render/offscreen_context_impl.h"
#include "render/vtk_scene_builder.h"
#include "render/window_image.h"

namespace maxillo::render {
namespace {

bool has_translucency(const Scene& scene) {
  return std::any_of(scene.meshes.begin(), scene.meshes.end(), [](const SceneMesh& m) { return m.opacity < 1.0; });
}

// With a colour bar, the scene keeps the left part of the image and the bar the right strip.
constexpr double kSceneWidthWithBar = 0.82;

const VertexScalars* first_scalars(const Scene& scene) {
  for (const auto& item : scene.meshes)
    if (item.scalars) return &*item.scalars;
  return nullptr;
}

vtkSmartPointer<vtkRenderer> build_colour_bar_renderer(const VertexScalars& scalars, const RenderSettings& settings) {
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetBackground(settings.background.r, settings.background.g, settings.background.b);
  renderer->SetViewport(kSceneWidthWithBar, 0.0, 1.0, 1.0);
  renderer->AddActor2D(make_colour_bar(scalars));
  return renderer;
}

vtkSmartPointer<vtkRenderer> build_scene_renderer(const Scene& scene, const RenderSettings& settings) {
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetBackground(settings.background.r, settings.background.g, settings.background.b);
  for (const auto& item : scene.meshes) renderer->AddActor(make_actor(item));
  if (first_scalars(scene)) renderer->SetViewport(0.0, 0.0, kSceneWidthWithBar, 1.0);

  // Key, fill, back and head lights that follow the camera: every view is lit alike.
  renderer->RemoveAllLights();
  auto lights = vtkSmartPointer<vtkLightKit>::New();
  lights->SetKeyLightIntensity(0.85);
  lights->AddLightsToRenderer(renderer);

  if (has_translucency(scene)) {
    renderer->SetUseDepthPeeling(true);
    // Each peel draws every translucent mesh again, and llvmpipe draws on the CPU. On the demo's plan views
    // (translucent skull, segments and their ghosts) 6 peels differ from 12 by at most 0.008 grey levels on average
    // (13 of 255 at worst, on fewer than 0.005 % of the values) and save 2.5 s of a 12 s `plan apply`; 3 peels
    // would differ by 0.24 on average.
    renderer->SetMaximumNumberOfPeels(6);
    renderer->SetOcclusionRatio(0.0);  // peel to the limit, never stop on a timing-dependent count
  }
  renderer->SetUseFXAA(true);  // smooth silhouettes (single-sample buffer, see OffscreenContext)
  return renderer;
}

// The camera was fitted to the whole image; a narrower viewport needs a wider view.
Camera widened_for_viewport(Camera spec, double viewport_width) {
  spec.parallel_scale_mm /= viewport_width;
  const double half_angle = spec.view_angle_deg / 2 * vtkMath::Pi() / 180;
  spec.view_angle_deg = 2 * std::atan(std::tan(half_angle) / viewport_width) * 180 / vtkMath::Pi();
  return spec;
}

void apply_camera(vtkRenderer& renderer, const Camera& spec) {
  vtkCamera* camera = renderer.GetActiveCamera();
  camera->SetFocalPoint(spec.focal_point.data());
  camera->SetPosition(spec.position.data());
  camera->SetViewUp(spec.view_up.data());
  camera->SetParallelProjection(spec.projection == Projection::Parallel);
  camera->SetParallelScale(spec.parallel_scale_mm);
  camera->SetViewAngle(spec.view_angle_deg);
  camera->OrthogonalizeViewUp();
  renderer.ResetCameraClippingRange();
}

}  // namespace

std::vector<RgbImage> render_scene(const Scene& scene, std::span<const Camera> cameras,
                                   const RenderSettings& settings) {
  OffscreenContext context(settings.size);
  auto& window = *context.impl().window;
  auto renderer = build_scene_renderer(scene, settings);
  window.AddRenderer(renderer);
  vtkSmartPointer<vtkRenderer> bar_renderer;
  if (const auto* scalars = first_scalars(scene)) {
    bar_renderer = build_colour_bar_renderer(*scalars, settings);
    window.AddRenderer(bar_renderer);
  }

  std::vector<RgbImage> images;
  for (const auto& camera : cameras) {
    apply_camera(*renderer, bar_renderer ? widened_for_viewport(camera, kSceneWidthWithBar) : camera);
    // The markers' labels are laid out anew for each camera: where they go depends on the view.
    const auto overlay = marker_props(*renderer, scene.markers);
    for (const auto& prop : overlay) renderer->AddViewProp(prop);
    window.Render();
    images.push_back(grab_window(window));
    for (const auto& prop : overlay) renderer->RemoveViewProp(prop);
    if (images.back().width != settings.size.width || images.back().height != settings.size.height)
      throw Error(ErrorCode::kRenderFailed, "OSMesa", "read back an image of the wrong size");
  }
  window.GetRenderers()->RemoveAllItems();
  return images;
}

void write_png(const RgbImage& image, const std::filesystem::path& path) {
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetDimensions(image.width, image.height, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* target = static_cast<std::uint8_t*>(data->GetScalarPointer());
  const std::size_t row = static_cast<std::size_t>(image.width) * 3;
  for (int y = 0; y < image.height; ++y)  // flip back to VTK's bottom-up rows
    std::memcpy(target + (image.height - 1 - y) * row, image.pixels.data() + y * row, row);

  auto writer = vtkSmartPointer<vtkPNGWriter>::New();
  writer->SetInputData(data);
  writer->WriteToMemoryOn();
  writer->Write();
  vtkUnsignedCharArray* encoded = writer->GetResult();
  if (!encoded || encoded->GetNumberOfValues() == 0)
    throw Error(ErrorCode::kWriteFailed, path.string(), "PNG encoding failed");
  write_file_atomically(path, std::span(reinterpret_cast<const std::byte*>(encoded->GetPointer(0)),
                                        static_cast<std::size_t>(encoded->GetNumberOfValues())));
}

RgbImage read_png(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) throw Error(ErrorCode::kFileNotFound, path.string(), "no such file");
  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  if (!reader->CanReadFile(path.c_str())) throw Error(ErrorCode::kBadValue, path.string(), "not a PNG file");
  reader->SetFileName(path.c_str());
  reader->Update();
  return from_vtk_image(*reader->GetOutput());
}

}  // namespace maxillo::render
