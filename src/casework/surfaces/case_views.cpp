#include "casework/surfaces/case_views.h"

#include <array>

#include "archive/artefact_kind.h"
#include "ceph/landmark_frame.h"
#include "core/atomic_file.h"
#include "core/temporary_folder.h"
#include "records/derivation.h"
#include "render/render_views.h"

namespace maxillo::casework {
namespace {

constexpr std::array kViews = {render::StandardView::Frontal, render::StandardView::Lateral,
                               render::StandardView::Oblique};

constexpr std::array kTissues = {ViewedTissue::Skin, ViewedTissue::Bone};

std::string caption_for(ViewedTissue tissue, render::StandardView view, const AnatomicalFrame& frame) {
  std::string caption = std::string(name_of(tissue)) + ", " + std::string(render::name_of(view));
  if (view == render::StandardView::Lateral) caption += " (right)";
  return caption + (frame.source == FrameSource::Frankfort ? "; Frankfort frame" : "; patient axes");
}

std::string artefact_kind(ViewedTissue tissue, render::StandardView view) {
  using render::StandardView;
  const bool skin = tissue == ViewedTissue::Skin;
  switch (view) {
    case StandardView::Frontal:
      return kind_name(skin ? ArtefactKind::kRenderSkinFrontal : ArtefactKind::kRenderBoneFrontal);
    case StandardView::Lateral:
    case StandardView::LeftLateral:  // not among the case's views
      return kind_name(skin ? ArtefactKind::kRenderSkinLateral : ArtefactKind::kRenderBoneLateral);
    case StandardView::Oblique:
      return kind_name(skin ? ArtefactKind::kRenderSkinOblique : ArtefactKind::kRenderBoneOblique);
  }
  return kind_name(ArtefactKind::kRenderSkinFrontal);
}

render::Scene scene_of(ViewedTissue tissue, const CaseSurfaces& surfaces) {
  render::Scene scene;
  if (tissue == ViewedTissue::Skin)
    scene.meshes.push_back({&surfaces.skin, render::kSkinTone, 1.0, std::nullopt});
  else
    scene.meshes.push_back({&surfaces.bone, render::kBoneIvory, 1.0, std::nullopt});
  return scene;
}

// Renders every tissue and view and stores each PNG as an artefact under `key`.
void render_and_store(Archive& archive, int64_t case_id, const CaseSurfaces& surfaces, const AnatomicalFrame& frame,
                      const ViewRecipe& recipe, const std::string& key, const Json& parameters) {
  auto skin_bounds = render::scene_bounds(scene_of(ViewedTissue::Skin, surfaces));
  std::vector<render::Camera> cameras;
  for (auto view : kViews) cameras.push_back(render::standard_camera(view, frame, skin_bounds, 1.0));
  render::RenderSettings settings;
  settings.size = {recipe.image_size_px, recipe.image_size_px};

  TemporaryFolder scratch("maxillo-views");
  for (auto tissue : kTissues) {
    auto images = render::render_scene(scene_of(tissue, surfaces), cameras, settings);
    for (size_t v = 0; v < kViews.size(); ++v) {
      auto file = scratch / (artefact_kind(tissue, kViews[v]) + ".png");
      render::write_png(images[v], file);
      auto sha = archive.store_object(read_file(file));
      archive.add_artefact(
          NewArtefact{case_id, artefact_kind(tissue, kViews[v]), sha, "image/png", key, parameters.dump()});
    }
  }
}

}  // namespace

std::string_view name_of(ViewedTissue tissue) { return tissue == ViewedTissue::Skin ? "skin" : "bone"; }

std::vector<CaseView> case_views(Archive& archive, int64_t case_id, const CaseSurfaces& surfaces,
                                 const LandmarkSet& landmarks, const ViewRecipe& recipe) {
  auto frame = anatomical_frame(landmarks);
  Json parameters{{"image_size_px", recipe.image_size_px}};
  auto key = records::derivation_key({surfaces.key, landmarks_hash(landmarks)}, parameters);

  bool all_stored = true;
  for (auto tissue : kTissues)
    for (auto view : kViews)
      all_stored = all_stored && archive.find_artefact(case_id, artefact_kind(tissue, view), key);
  if (!all_stored) render_and_store(archive, case_id, surfaces, frame, recipe, key, parameters);

  std::vector<CaseView> views;
  for (auto tissue : kTissues)
    for (auto view : kViews) {
      auto artefact = archive.find_artefact(case_id, artefact_kind(tissue, view), key);
      views.push_back({tissue, view, archive.object_path(artefact->object_sha256), caption_for(tissue, view, frame)});
    }
  return views;
}

}  // namespace maxillo::casework
