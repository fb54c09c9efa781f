#pragma once
// Renders a Scene off-screen (OSMesa, no display) into RGB images and PNG files.
//
// Look: light grey background, a vtkLightKit (key, fill, back and head lights) so every view
// is lit the same way, translucent meshes sorted by depth peeling (skin over bone), and a
// colour bar on the right when a mesh carries per-vertex scalars. Rendering is deterministic:
// the same scene, camera and size give the same pixels.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "render/offscreen_context.h"
#include "render/scene.h"

namespace maxillo::render {

inline constexpr ColourRGB kBackgroundGrey{0.94, 0.94, 0.95};

struct RenderSettings {
  ImageSize size{1024, 1024};
  ColourRGB background = kBackgroundGrey;
};

// 8-bit RGB pixels, rows from the top of the image down, 3 bytes per pixel.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // size == width * height * 3

  const std::uint8_t* at(int x, int y) const { return &pixels[3 * (static_cast<std::size_t>(y) * width + x)]; }
};

// One image per camera, in order. Throws Error(RenderFailed) when rendering fails and
// Error(BadValue) for scalars whose count differs from the mesh's vertex count.
// Asserts (misuse) on a null mesh pointer.
std::vector<RgbImage> render_scene(const Scene& scene, std::span<const Camera> cameras,
                                   const RenderSettings& settings = {});

// Encodes PNG and writes it atomically (temporary file + rename). Throws Error(WriteFailed).
void write_png(const RgbImage& image, const std::filesystem::path& path);

// Decodes a PNG file into RGB (alpha, if any, is dropped). Throws Error naming the path.
RgbImage read_png(const std::filesystem::path& path);

}  // namespace maxillo::render
