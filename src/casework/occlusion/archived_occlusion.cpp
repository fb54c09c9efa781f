#include "casework/occlusion/archived_occlusion.h"

#include <span>

#include "occlusion/occlusion_files.h"
#include "records/derivation.h"
#include "records/occlusion_archive.h"
#include "render/anatomical_views.h"
#include "render/render_views.h"

namespace maxillo::casework {

void store_occlusion_run(Archive& archive, int64_t case_id, const OcclusionRun& run,
                         const std::vector<std::string>& input_hashes, const AnatomicalFrame& frame) {
  records::OcclusionToStore stored;
  stored.case_id = case_id;
  stored.inputs_hash =
      records::derivation_key(input_hashes, {{"start_transform", occlusion::transform_to_json(run.start)},
                                             {"contact_threshold_mm", run.contact_threshold_mm},
                                             {"splint", run.splint.has_value()}});
  stored.folder = run.folder;
  stored.splint = run.splint.has_value();
  if (run.splint) {
    stored.splint_render = run.folder / "splint.png";
    render_splint(run, frame, stored.splint_render);
  }
  records::store_occlusion(archive, stored);
}

void render_splint(const OcclusionRun& run, const AnatomicalFrame& frame, const std::filesystem::path& png) {
  render::Scene scene;
  scene.meshes.push_back({&run.lower, render::kTeethWhite, 1.0, std::nullopt});
  if (run.splint) scene.meshes.push_back({&run.splint->mesh, render::ColourRGB{0.45, 0.7, 0.95}, 0.85, std::nullopt});
  const render::Bounds bounds = render::scene_bounds(scene);
  // From the front and 45 degrees above, so the occlusal side of the splint shows: the frontal
  // view of a frame pitched down (still right-handed: anterior x left = superior).
  AnatomicalFrame tilted = frame;
  tilted.anterior = (frame.anterior + frame.superior).normalized();
  tilted.superior = (frame.superior - frame.anterior).normalized();
  const render::Camera camera = render::standard_camera(render::StandardView::Frontal, tilted, bounds, 1.0);
  render::RenderSettings settings;
  settings.size = {700, 700};
  render::write_png(render::render_scene(scene, std::span(&camera, 1), settings).front(), png);
}

}  // namespace maxillo::casework
