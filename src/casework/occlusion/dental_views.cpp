#include "casework/occlusion/dental_views.h"

#include <span>

#include "core/temporary_folder.h"
#include "geometry/aabb_tree.h"
#include "records/derivation.h"
#include "records/stored_artefact.h"
#include "render/anatomical_views.h"
#include "render/render_views.h"
#include "render/view_files.h"

namespace maxillo::casework {
namespace {

using records::DentalArch;

constexpr double kFitMapRangeMm = 1.0;  // the fit's colour scale: 0 (on the CT's teeth) to this
constexpr render::ColourRGB kScannedCrownColour{0.35, 0.6, 0.95};

// Each scan point's distance to the CT's teeth (capped at twice the colour scale).
std::vector<double> distances_to(const TriangleMesh& placed, const TriangleMesh& teeth) {
  const AabbTree tree(teeth);
  std::vector<double> distances(size_t(placed.vertex_count()), 2 * kFitMapRangeMm);
  for (Eigen::Index v = 0; v < placed.vertex_count(); ++v) {
    const auto nearest = tree.nearest(placed.vertices.row(v).transpose(), 2 * kFitMapRangeMm);
    if (nearest.face >= 0) distances[size_t(v)] = nearest.distance;
  }
  return distances;
}

// The augmented model's surface split in two: the faces whose corners all lie on a scanned crown
// (within 0.05 mm of the placed scan) and the others, the CT's.
std::pair<TriangleMesh, TriangleMesh> crowns_and_ct(const TriangleMesh& augmented, const TriangleMesh& placed) {
  const AabbTree scan(placed);
  std::vector<uint8_t> on_scan(size_t(augmented.vertex_count()));
  for (Eigen::Index v = 0; v < augmented.vertex_count(); ++v)
    on_scan[size_t(v)] = scan.nearest(augmented.vertices.row(v).transpose(), 0.05).face >= 0;
  TriangleMesh crowns{augmented.vertices, {}}, ct{augmented.vertices, {}};
  std::vector<Eigen::Vector3i> crown_faces, ct_faces;
  for (Eigen::Index f = 0; f < augmented.face_count(); ++f) {
    const Eigen::Vector3i face = augmented.faces.row(f).transpose();
    (on_scan[size_t(face(0))] && on_scan[size_t(face(1))] && on_scan[size_t(face(2))] ? crown_faces : ct_faces)
        .push_back(face);
  }
  for (auto [mesh, faces] : {std::pair{&crowns, &crown_faces}, {&ct, &ct_faces}}) {
    mesh->faces.resize(Eigen::Index(faces->size()), 3);
    for (size_t f = 0; f < faces->size(); ++f) mesh->faces.row(Eigen::Index(f)) = (*faces)[f].transpose();
  }
  return {std::move(crowns), std::move(ct)};
}

}  // namespace

void render_dental_fit(const TriangleMesh& placed, const TriangleMesh& teeth, DentalArch arch,
                       const AnatomicalFrame& frame, const std::filesystem::path& png) {
  render::Scene scene;
  render::VertexScalars scalars{distances_to(placed, teeth), 0, kFitMapRangeMm, render::ColourMap::Sequential,
                                "distance to the CT's teeth (mm)"};
  scene.meshes.push_back({&placed, render::kTeethWhite, 1.0, scalars});
  // The frontal view of a frame turned so that its "front" is the occlusal side and its "up" the
  // patient's front (right-handed: anterior x left = superior).
  AnatomicalFrame occlusal = frame;
  const double side = arch == DentalArch::kUpper ? -1 : 1;
  occlusal.anterior = side * frame.superior;
  occlusal.superior = frame.anterior;
  occlusal.left = side * frame.left * -1;
  const render::Camera camera =
      render::standard_camera(render::StandardView::Frontal, occlusal, render::scene_bounds(scene), 1.0);
  render::RenderSettings settings;
  settings.size = {700, 700};
  render::write_png(render::render_scene(scene, std::span(&camera, 1), settings).front(), png);
}

// Both jaws' augmented dentitions, the scanned crowns in blue and the CT's teeth in ivory, from
// the front and the right: "augmented-frontal", "augmented-lateral" (dental-render pictures).
void store_augmented_pictures(Archive& archive, int64_t case_id, const CaseDentalRegistration& registered,
                              const AnatomicalFrame& frame) {
  std::vector<std::pair<TriangleMesh, TriangleMesh>> parts;
  std::vector<std::string> keys;
  for (const auto& arch : registered.arches)
    if (arch.augmented.face_count() > 0) {
      parts.push_back(crowns_and_ct(arch.augmented, arch.placed));
      keys.push_back(arch.scan.object_sha256);
    }
  if (parts.empty()) return;
  render::Scene scene;
  for (const auto& [crowns, ct] : parts) {
    scene.meshes.push_back({&crowns, kScannedCrownColour, 1.0, std::nullopt});
    scene.meshes.push_back({&ct, render::kBoneIvory, 1.0, std::nullopt});
  }
  TemporaryFolder scratch("maxillo-augmented");
  render::RenderSettings settings;
  settings.size = {700, 700};
  const render::StandardView views[] = {render::StandardView::Frontal, render::StandardView::Lateral};
  const std::string key = records::derivation_key(keys, {{"pictures", "augmented"}});
  for (const auto& view : render::render_view_files(scene, frame, views, scratch.path(), "augmented-", settings))
    records::store_picture(archive, case_id, ArtefactKind::kDentalRender, key, view.png);
}

}  // namespace maxillo::casework
