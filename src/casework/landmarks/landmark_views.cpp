#include "casework/landmarks/landmark_views.h"

#include <array>

#include "archive/artefact_kind.h"
#include "ceph/landmark_frame.h"
#include "core/temporary_folder.h"
#include "records/derivation.h"
#include "records/stored_artefact.h"
#include "render/render_views.h"

namespace maxillo::casework {
namespace {

using render::StandardView;

constexpr std::array kLandmarkViews = {StandardView::Frontal, StandardView::Lateral, StandardView::LeftLateral};
constexpr double kSkinOpacityOverLandmarks = 0.3;  // the bone shows through; the skin's landmarks sit on its outline

bool shown_in(StandardView view, const std::string& label) {
  const auto base = bilateral_base(label);
  switch (view) {
    case StandardView::Lateral: return !base || label.back() == 'R';
    case StandardView::LeftLateral: return base && label.back() == 'L';
    default: return true;
  }
}

std::string landmark_caption(StandardView view) {
  switch (view) {
    case StandardView::Lateral: return "right lateral: midline and right-sided landmarks";
    case StandardView::LeftLateral: return "left lateral: left-sided landmarks";
    default: return "frontal: every landmark";
  }
}

std::string landmark_picture_name(StandardView view) { return "landmarks-" + std::string(render::name_of(view)); }

render::ColourRGB colour_of(const records::StoredLandmarks& stored, const std::string& label) {
  if (!stored.automatic) return kGivenLandmarkColour;
  return stored.automatic->flagged.contains(label) ? kFlaggedLandmarkColour : kAutomaticLandmarkColour;
}

// What the pictures depend on besides the surfaces: the points, their source and their flags.
Json picture_parameters(const records::StoredLandmarks& stored, const ViewRecipe& recipe) {
  Json flagged = Json::array();
  if (stored.automatic)
    for (const auto& [label, why] : stored.automatic->flagged) flagged.push_back(label);
  return Json{{"image_size_px", recipe.image_size_px},
              {"automatic", stored.automatic.has_value()},
              {"flagged", flagged},
              {"look", 1}};  // raise when the pictures' look changes
}

void render_and_store_landmarks(Archive& archive, int64_t case_id, const CaseSurfaces& surfaces,
                                const records::StoredLandmarks& stored, const ViewRecipe& recipe,
                                const std::string& key) {
  const auto frame = anatomical_frame(stored.landmarks);
  render::Scene skin_only;
  skin_only.meshes.push_back({&surfaces.skin, render::kSkinTone, 1.0, std::nullopt});
  const auto framing = render::scene_bounds(skin_only);  // the case's views frame the skin too

  render::RenderSettings settings;
  settings.size = {recipe.image_size_px, recipe.image_size_px};
  TemporaryFolder scratch("maxillo-landmark-views");
  for (auto view : kLandmarkViews) {
    render::Scene scene;
    scene.meshes.push_back({&surfaces.bone, render::kBoneIvory, 1.0, std::nullopt});
    scene.meshes.push_back({&surfaces.skin, render::kSkinTone, kSkinOpacityOverLandmarks, std::nullopt});
    scene.markers = landmark_markers(stored, view);
    const auto camera = render::standard_camera(view, frame, framing, 1.0);
    const auto images = render::render_scene(scene, std::span(&camera, 1), settings);
    const auto file = scratch / (landmark_picture_name(view) + ".png");
    render::write_png(images.front(), file);
    records::store_picture(archive, case_id, ArtefactKind::kLandmarkRender, key, file);
  }
}

}  // namespace

std::vector<render::SceneMarker> landmark_markers(const records::StoredLandmarks& stored, StandardView view) {
  std::vector<render::SceneMarker> markers;
  for (const auto& l : stored.landmarks)
    if (shown_in(view, l.label)) markers.push_back({l.position, l.label, colour_of(stored, l.label)});
  return markers;
}

std::vector<LandmarkView> landmark_views(Archive& archive, int64_t case_id, const CaseSurfaces& surfaces,
                                         const records::StoredLandmarks& stored, const ViewRecipe& recipe) {
  const Json parameters = picture_parameters(stored, recipe);
  const auto key = records::derivation_key({surfaces.key, landmarks_hash(stored.landmarks)}, parameters);

  auto find_all = [&] {
    const auto artefacts = archive.artefacts(case_id);
    std::vector<LandmarkView> views;
    for (auto view : kLandmarkViews)
      if (const auto* found =
              records::newest_with_key(artefacts, ArtefactKind::kLandmarkRender, key, landmark_picture_name(view)))
        views.push_back({view, archive.object_path(found->object_sha256), landmark_caption(view)});
    return views;
  };
  auto views = find_all();
  if (views.size() == kLandmarkViews.size()) return views;
  render_and_store_landmarks(archive, case_id, surfaces, stored, recipe, key);
  return find_all();
}

}  // namespace maxillo::casework
