#include "render/view_files.h"

#include <string>

#include "core/error.h"

namespace maxillo::render {

std::vector<ViewFile> render_view_files(const Scene& scene, const AnatomicalFrame& frame,
                                        std::span<const StandardView> views, const std::filesystem::path& folder,
                                        std::string_view prefix, const RenderSettings& settings) {
  return render_view_files(scene, frame, views, folder, prefix, settings, scene_bounds(scene));
}

std::vector<ViewFile> render_view_files(const Scene& scene, const AnatomicalFrame& frame,
                                        std::span<const StandardView> views, const std::filesystem::path& folder,
                                        std::string_view prefix, const RenderSettings& settings, const Bounds& bounds) {
  if (bounds.empty()) throw Error(ErrorCode::kEmptyResult, "scene", "nothing to render: no vertices");
  const double aspect = double(settings.size.width) / settings.size.height;
  std::vector<Camera> cameras;
  std::vector<ViewFile> files;
  for (auto view : views) {
    cameras.push_back(standard_camera(view, frame, bounds, aspect));
    files.push_back({view, folder / (std::string(prefix) + std::string(name_of(view)) + ".png")});
  }
  const auto images = render_scene(scene, cameras, settings);
  for (std::size_t i = 0; i < images.size(); ++i) write_png(images[i], files[i].png);
  return files;
}

}  // namespace maxillo::render
