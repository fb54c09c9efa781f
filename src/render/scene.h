#pragma once
// What to draw and from where: plain structs, no VTK. Positions in the patient LPS frame, mm.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/triangle_mesh.h"

namespace maxillo::render {

struct ColourRGB {
  double r = 0, g = 0, b = 0;  // each in [0, 1]
};

// Tissue colours used by the reports, so every picture of a case looks the same.
inline constexpr ColourRGB kSkinTone{0.93, 0.76, 0.65};
inline constexpr ColourRGB kBoneIvory{0.96, 0.94, 0.85};
inline constexpr ColourRGB kTeethWhite{1.0, 1.0, 0.97};

enum class ColourMap {
  Diverging,   // blue - white - red, for signed values (distance maps: negative = inside)
  Sequential,  // dark blue - green - yellow (viridis-like), for magnitudes (displacement)
};

// One value per vertex of the mesh, coloured through `map` over [range_min, range_max]
// (values outside are clamped to the end colours). Shown with a colour bar titled `title`.
struct VertexScalars {
  std::vector<double> values;  // size == mesh->vertex_count()
  double range_min = 0;
  double range_max = 1;
  ColourMap map = ColourMap::Diverging;
  std::string title;  // e.g. "distance (mm)"
};

struct SceneMesh {
  const TriangleMesh* mesh = nullptr;  // not owned; must outlive the render call
  ColourRGB colour = kBoneIvory;       // used where there are no scalars
  double opacity = 1.0;                // 1 = opaque; skin over bone reads well at ~0.45
  std::optional<VertexScalars> scalars;
};

// A marked point (a landmark), drawn over the meshes so that a point inside the skull (the sella)
// stays visible: a disc with a dark rim, and its label beside it where it hides no other label
// or marker (render/label_layout.h), joined to the disc by a line when it had to move away.
struct SceneMarker {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // LPS mm
  std::string label;
  ColourRGB colour;
};

struct Scene {
  std::vector<SceneMesh> meshes;
  std::vector<SceneMarker> markers;  // drawn in this order; earlier labels get the nearer places
};

enum class Projection {
  Parallel,     // orthographic: lengths in the image plane are true to scale (the default)
  Perspective,  // a narrow perspective (view_angle_deg), like a photograph from afar
};

struct Camera {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();     // LPS mm
  Eigen::Vector3d focal_point = Eigen::Vector3d::Zero();  // LPS mm, the centre of the image
  Eigen::Vector3d view_up = Eigen::Vector3d::UnitZ();     // unit, appears vertical (up) in the image
  Projection projection = Projection::Parallel;
  double parallel_scale_mm = 100;  // Parallel: half the image height, in mm
  double view_angle_deg = 15;      // Perspective: full vertical angle
};

// Axis-aligned bounds of a scene's meshes (LPS mm; markers do not count). Empty when min > max.
struct Bounds {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(1e300);
  Eigen::Vector3d max = Eigen::Vector3d::Constant(-1e300);
  bool empty() const { return (min.array() > max.array()).any(); }
  Eigen::Vector3d centre() const { return 0.5 * (min + max); }
};

Bounds scene_bounds(const Scene& scene);

}  // namespace maxillo::render
