#include "archive/artefact_kind.h"

#include <iterator>

namespace maxillo {

// kAllArtefactKinds lists every kind: the last enumerator closes the list.
static_assert(std::size(kAllArtefactKinds) == size_t(ArtefactKind::kAugmentedDentition) + 1);

std::string kind_name(ArtefactKind kind) {
  switch (kind) {
    case ArtefactKind::kLandmarks: return "landmarks";
    case ArtefactKind::kPlan: return "plan";
    case ArtefactKind::kPlanResult: return "plan-result";
    case ArtefactKind::kSurfaceSkin: return "surface-skin";
    case ArtefactKind::kSurfaceBone: return "surface-bone";
    case ArtefactKind::kRenderSkinFrontal: return "render-skin-frontal";
    case ArtefactKind::kRenderSkinLateral: return "render-skin-lateral";
    case ArtefactKind::kRenderSkinOblique: return "render-skin-oblique";
    case ArtefactKind::kRenderBoneFrontal: return "render-bone-frontal";
    case ArtefactKind::kRenderBoneLateral: return "render-bone-lateral";
    case ArtefactKind::kRenderBoneOblique: return "render-bone-oblique";
    case ArtefactKind::kOcclusion: return "occlusion";
    case ArtefactKind::kOcclusionogram: return "occlusionogram";
    case ArtefactKind::kSplint: return "splint";
    case ArtefactKind::kSplintRender: return "splint-render";
    case ArtefactKind::kSimulation: return "simulation";
    case ArtefactKind::kSimulationImage: return "simulation-image";
    case ArtefactKind::kValidation: return "validation";
    case ArtefactKind::kValidationDistances: return "validation-distances";
    case ArtefactKind::kValidationImage: return "validation-image";
    case ArtefactKind::kChartWits: return "chart-wits";
    case ArtefactKind::kReport: return "report";
    case ArtefactKind::kOrientation: return "orientation";
    case ArtefactKind::kLandmarkRender: return "landmark-render";
    case ArtefactKind::kDentalScan: return "dental-scan";
    case ArtefactKind::kDentalRegistration: return "dental-registration";
    case ArtefactKind::kDentalRender: return "dental-render";
    case ArtefactKind::kAugmentedDentition: return "augmented-dentition";
  }
  return "unknown";
}

std::optional<ArtefactKind> parse_artefact_kind(std::string_view name) {
  for (ArtefactKind kind : kAllArtefactKinds)
    if (kind_name(kind) == name) return kind;
  return std::nullopt;
}

}  // namespace maxillo
