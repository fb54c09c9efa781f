#pragma once
// The standard clinical views of a scene as PNG files: what `maxillo report` and
// `maxillo demo` need in one call.
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

#include "render/anatomical_views.h"
#include "render/render_views.h"

namespace maxillo::render {

struct ViewFile {
  StandardView view;
  std::filesystem::path png;  // folder / (prefix + name_of(view) + ".png")
};

// Renders each view (parallel projection, cameras from standard_camera with the image's
// aspect) in one OSMesa context and writes the PNGs atomically into an existing folder.
// Throws Error(EmptyResult) for a scene without vertices, and the errors of render_scene
// and write_png.
std::vector<ViewFile> render_view_files(const Scene& scene, const AnatomicalFrame& frame,
                                        std::span<const StandardView> views, const std::filesystem::path& folder,
                                        std::string_view prefix = "", const RenderSettings& settings = {});
// As above, with the cameras framing `framing` instead of the scene's bounds: a close-up of
// part of the scene, or the same cameras for several scenes (before and after pictures).
std::vector<ViewFile> render_view_files(const Scene& scene, const AnatomicalFrame& frame,
                                        std::span<const StandardView> views, const std::filesystem::path& folder,
                                        std::string_view prefix, const RenderSettings& settings, const Bounds& framing);

}  // namespace maxillo::render
