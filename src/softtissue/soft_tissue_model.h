#pragma once
// The soft tissue models a face prediction can use (thesis ch. 6): the mass tensor model, linear
// FEM, the mass-spring model and non-linear (neo-Hookean) FEM. One table holds what the rest of
// the program needs to know of each: its short name for commands and files, its title for
// reports, and whether the uncertainty band re-solves with it. The commands (`simulate`,
// `validate`, `bench cube`), the case workflow and the benchmarks read the table, so a new model
// is added here (and its solver where the face is solved, casework/soft_tissue_prediction.cpp).
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace maxillo::softtissue {

enum class SoftTissueModel { kMassTensor, kLinearFem, kMassSpring, kNonlinearFem };

struct SoftTissueModelInfo {
  SoftTissueModel model;
  std::string_view name;     // "mtm", "fem", "msm", "nfem"
  std::string_view title;    // "mass tensor model", ...
  bool in_uncertainty_band;  // re-solved for the uncertainty band (casework/case_simulation.h)
};

// Every model, in the order commands list them.
std::span<const SoftTissueModelInfo> soft_tissue_models();
const SoftTissueModelInfo& model_info(SoftTissueModel model);

std::string_view model_name(SoftTissueModel model);  // "mtm", "fem", "msm", "nfem"
std::optional<SoftTissueModel> parse_model(std::string_view name);
std::string_view model_title(SoftTissueModel model);  // "mass tensor model", ...
// The names, for a command's check of its --model option.
std::vector<std::string> model_names();
// "mtm (mass tensor model), fem (linear FEM), ... or nfem (...)", for a command's help.
std::string model_choices();

}  // namespace maxillo::softtissue
