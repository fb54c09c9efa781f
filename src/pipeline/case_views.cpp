#include "pipeline/case_views.h"

#include <array>

#include "core/atomic_file.h"
#include "core/sha256.h"
#include "core/temporary_folder.h"
#include "pipeline/derivation.h"
#include "render/render_views.h"

namespace maxillo::pipeline {
namespace {

constexpr std::array kViews = {render::StandardView::Frontal, render::StandardView::Lateral,
                               render::StandardView::Oblique};

std::string landmarks_hash(const LandmarkSet& landmarks) {
  Sha256 hash;
  for (const auto& l : landmarks) {
    hash.update(l.label);
    for (double c : l.position) hash.update(std::to_string(c));
  }
  return hash.hex_digest();
}

std::string caption_for(render::StandardView view, const render::AnatomicalFrame& frame) {
  std::string name(render::name_of(view));
  if (view == render::StandardView::Lateral) name += " (right)";
  return name + (frame.source == render::FrameSource::Frankfort ? ", Frankfort horizontal frame"
                                                                : ", patient axes (no landmarks)");
}

std::string artefact_kind(render::StandardView view) { return "render-" + std::string(render::name_of(view)); }

// Renders all three views and stores each PNG as an artefact under `key`.
void render_and_store(Archive& archive, int64_t case_id, const CaseSurfaces& surfaces,
                      const render::AnatomicalFrame& frame, const ViewRecipe& recipe, const std::string& key,
                      const Json& parameters) {
  render::Scene scene;
  scene.meshes.push_back({&surfaces.bone, render::kBoneIvory, 1.0, std::nullopt});
  scene.meshes.push_back({&surfaces.skin, render::kSkinTone, recipe.skin_opacity, std::nullopt});
  auto bounds = render::scene_bounds(scene);
  std::vector<render::Camera> cameras;
  for (auto view : kViews) cameras.push_back(render::standard_camera(view, frame, bounds, 1.0));
  render::RenderSettings settings;
  settings.size = {recipe.image_size_px, recipe.image_size_px};
  auto images = render::render_scene(scene, cameras, settings);

  TemporaryFolder scratch("maxillo-views");
  for (size_t v = 0; v < kViews.size(); ++v) {
    auto file = scratch / (std::string(render::name_of(kViews[v])) + ".png");
    render::write_png(images[v], file);
    auto sha = archive.store_object(read_file(file));
    archive.add_artefact(NewArtefact{case_id, artefact_kind(kViews[v]), sha, "image/png", key, parameters.dump()});
  }
}

}  // namespace

std::vector<CaseView> case_views(Archive& archive, int64_t case_id, const CaseSurfaces& surfaces,
                                 const LandmarkSet& landmarks, const ViewRecipe& recipe) {
  auto frame = render::anatomical_frame(landmarks);
  Json parameters{{"image_size_px", recipe.image_size_px}, {"skin_opacity", recipe.skin_opacity}};
  auto key = derivation_key({surfaces.key, landmarks_hash(landmarks)}, parameters);

  bool all_stored = true;
  for (auto view : kViews) all_stored = all_stored && archive.find_artefact(case_id, artefact_kind(view), key);
  if (!all_stored) render_and_store(archive, case_id, surfaces, frame, recipe, key, parameters);

  std::vector<CaseView> views;
  for (auto view : kViews) {
    auto artefact = archive.find_artefact(case_id, artefact_kind(view), key);
    views.push_back({view, archive.object_path(artefact->object_sha256), caption_for(view, frame)});
  }
  return views;
}

}  // namespace maxillo::pipeline

