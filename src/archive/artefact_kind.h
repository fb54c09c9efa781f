#pragma once
// What a case's derived artefact is: the one list of artefact kinds. The index stores the name
// (artefact.kind) and every module that stores or looks up an artefact names its kind through
// this enum, so a kind is spelt in one place only.
#include <optional>
#include <string>
#include <string_view>

namespace maxillo {

enum class ArtefactKind {
  kLandmarks,          // a landmark set (3D Slicer markups JSON), optionally of a time point
  kPlan,               // a saved plan version (plan JSON)
  kPlanResult,         // the plan applied to the case (plan_result_record.h)
  kSurfaceSkin,        // the report's skin surface (PLY)
  kSurfaceBone,        // the report's bone surface (PLY)
  kRenderSkinFrontal,  // standard views of the surfaces (PNG)
  kRenderSkinLateral,
  kRenderSkinOblique,
  kRenderBoneFrontal,
  kRenderBoneLateral,
  kRenderBoneOblique,
  kOcclusion,            // the final occlusion's numbers (JSON)
  kOcclusionogram,       // its occlusionogram (PNG)
  kSplint,               // the surgical splint (STL)
  kSplintRender,         // a render of the splint on the lower arch (PNG)
  kSimulation,           // a face prediction's summary (JSON, simulation_summary.h)
  kSimulationImage,      // its pictures (PNG)
  kValidation,           // a validation's numbers (JSON)
  kValidationDistances,  // the face's per-vertex distances of a validation (JSON)
  kValidationImage,      // a validation's pictures (PNG)
  kChartWits,            // the Wits appraisal over the follow-up (PNG)
  kReport,               // the consultation report (PDF)
  kOrientation,          // the CT's header checked against the anatomy, or confirmed by hand (JSON)
  kLandmarkRender,       // the landmarks drawn on bone and skin, one picture per view (PNG)
  kDentalScan,           // a dental arch scan as imported, in its scanner's frame (PLY)
  kDentalRegistration,   // an arch scan placed onto the CT's teeth: its pose and fit (JSON)
  kDentalRender,         // the augmented dentition and each arch's fit, pictured (PNG)
  kAugmentedDentition,   // a jaw's CT teeth with the scanned crowns in their place (PLY)
};

// Every kind, in the order above (for tables and tests).
inline constexpr ArtefactKind kAllArtefactKinds[] = {
    ArtefactKind::kLandmarks,           ArtefactKind::kPlan,
    ArtefactKind::kPlanResult,          ArtefactKind::kSurfaceSkin,
    ArtefactKind::kSurfaceBone,         ArtefactKind::kRenderSkinFrontal,
    ArtefactKind::kRenderSkinLateral,   ArtefactKind::kRenderSkinOblique,
    ArtefactKind::kRenderBoneFrontal,   ArtefactKind::kRenderBoneLateral,
    ArtefactKind::kRenderBoneOblique,   ArtefactKind::kOcclusion,
    ArtefactKind::kOcclusionogram,      ArtefactKind::kSplint,
    ArtefactKind::kSplintRender,        ArtefactKind::kSimulation,
    ArtefactKind::kSimulationImage,     ArtefactKind::kValidation,
    ArtefactKind::kValidationDistances, ArtefactKind::kValidationImage,
    ArtefactKind::kChartWits,           ArtefactKind::kReport,
    ArtefactKind::kOrientation,         ArtefactKind::kLandmarkRender,
    ArtefactKind::kDentalScan,          ArtefactKind::kDentalRegistration,
    ArtefactKind::kDentalRender,        ArtefactKind::kAugmentedDentition};

// The name the index stores: "landmarks", "plan-result", "render-skin-frontal", ...
std::string kind_name(ArtefactKind kind);
// The kind of a stored name; none for a name this program does not know (a newer program's).
std::optional<ArtefactKind> parse_artefact_kind(std::string_view name);

}  // namespace maxillo
