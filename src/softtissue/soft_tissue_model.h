#pragma once
// The soft tissue models a face prediction can use (thesis ch. 6): the mass tensor model, linear
// FEM, the mass-spring model and non-linear (neo-Hookean) FEM, with their short names for
// commands and files and their titles for reports.
#include <optional>
#include <string_view>

namespace maxillo::softtissue {

enum class SoftTissueModel { kMassTensor, kLinearFem, kMassSpring, kNonlinearFem };
std::string_view model_name(SoftTissueModel model);  // "mtm", "fem", "msm", "nfem"
std::optional<SoftTissueModel> parse_model(std::string_view name);
std::string_view model_title(SoftTissueModel model);  // "mass tensor model", ...

}  // namespace maxillo::softtissue
