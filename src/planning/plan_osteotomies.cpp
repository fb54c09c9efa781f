// The plan's osteotomies as cut planes: defaults come from the landmarks (osteotomy.h).
#include "planning/plan.h"

namespace maxillo::planning {

Osteotomies resolve_osteotomies(const PlanOsteotomies& spec, const LandmarkSet& landmarks) {
  auto plane_or = [](const std::optional<CutSpec>& cut, auto make_default) -> std::optional<CutPlane> {
    if (!cut) return std::nullopt;
    if (cut->kind == CutSpec::Kind::Plane) return cut->plane;
    return make_default(*cut);
  };
  Osteotomies cuts;
  cuts.le_fort_i = plane_or(spec.le_fort_i, [&](const CutSpec& c) { return default_le_fort_i(landmarks, c.variant); });
  cuts.pterygomaxillary =
      plane_or(spec.pterygomaxillary, [&](const CutSpec&) { return default_pterygomaxillary(landmarks); });
  cuts.genioplasty = plane_or(spec.genioplasty, [&](const CutSpec&) { return default_genioplasty(landmarks); });
  // BSSO planes are always explicit (plan validation refuses "default").
  if (spec.bsso_right) cuts.bsso_right = spec.bsso_right->plane;
  if (spec.bsso_left) cuts.bsso_left = spec.bsso_left->plane;
  return cuts;
}

}  // namespace maxillo::planning
