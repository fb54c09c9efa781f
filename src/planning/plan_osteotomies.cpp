// The plan's osteotomies as cut planes: defaults come from the landmarks (osteotomy.h).
#include "planning/plan.h"

#include "core/error.h"

namespace maxillo::planning {

namespace {

// The plane through three points, its normal towards the side of `moving` (the landmark of the
// segment the cut frees: it is the side that moves).
CutPlane plane_through(const std::array<Eigen::Vector3d, 3>& p, const LandmarkSet& landmarks, const std::string& moving,
                       const std::string& cut) {
  auto reference = find_landmark(landmarks, moving);
  if (!reference)
    throw Error(ErrorCode::kBadValue, cut, "a cut given by points needs the landmark " + moving + " to tell its sides");
  CutPlane plane{(p[0] + p[1] + p[2]) / 3.0, (p[1] - p[0]).cross(p[2] - p[0]).normalized()};
  if (plane.side(*reference) < 0) plane.normal = -plane.normal;
  return plane;
}

}  // namespace

Osteotomies resolve_osteotomies(const PlanOsteotomies& spec, const LandmarkSet& landmarks) {
  // `moving`: the landmark on the part each cut frees (for a cut given by points).
  auto plane_or = [&](const std::optional<CutSpec>& cut, const std::string& moving, const std::string& name,
                      auto make_default) -> std::optional<CutPlane> {
    if (!cut) return std::nullopt;
    if (cut->kind == CutSpec::Kind::Plane) return cut->plane;
    if (cut->kind == CutSpec::Kind::Points) return plane_through(cut->points, landmarks, moving, name);
    return make_default(*cut);
  };
  Osteotomies cuts;
  cuts.le_fort_i = plane_or(spec.le_fort_i, "U1", "Le Fort I",
                            [&](const CutSpec& c) { return default_le_fort_i(landmarks, c.variant); });
  cuts.pterygomaxillary = plane_or(spec.pterygomaxillary, "U1", "pterygomaxillary",
                                   [&](const CutSpec&) { return default_pterygomaxillary(landmarks); });
  cuts.genioplasty =
      plane_or(spec.genioplasty, "Me", "genioplasty", [&](const CutSpec&) { return default_genioplasty(landmarks); });
  cuts.bsso_right =
      plane_or(spec.bsso_right, "L1", "BSSO right", [&](const CutSpec&) { return default_bsso(landmarks).first; });
  cuts.bsso_left =
      plane_or(spec.bsso_left, "L1", "BSSO left", [&](const CutSpec&) { return default_bsso(landmarks).second; });
  return cuts;
}

}  // namespace maxillo::planning
