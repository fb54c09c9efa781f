#include "softtissue/soft_tissue_model.h"

#include <array>

namespace maxillo::softtissue {
namespace {

// The mass-spring model stays out of the uncertainty band: on the face models its answer lies
// ~6 mm (P95) from the mass tensor and FEM answers, which agree to 0.1 mm, so it would dominate
// the band. The non-linear FEM stays out too: it is the slowest by far and does not converge on
// every real head (docs/ARCHITECTURE.md, issue 34). `bench face` times the three models that
// solve the linear problem on the phantom; `bench face --real` solves with every model.
constexpr std::array kModels = {
    SoftTissueModelInfo{SoftTissueModel::kMassTensor, "mtm", "mass tensor model", solve_mass_tensor_model, true, true},
    SoftTissueModelInfo{SoftTissueModel::kLinearFem, "fem", "linear FEM", solve_linear_fem, true, true},
    SoftTissueModelInfo{SoftTissueModel::kMassSpring, "msm", "mass-spring model", solve_mass_spring_model, false, true},
    SoftTissueModelInfo{SoftTissueModel::kNonlinearFem, "nfem", "non-linear FEM (neo-Hookean)", solve_nonlinear_fem,
                        false, false}};

}  // namespace

std::span<const SoftTissueModelInfo> soft_tissue_models() { return kModels; }

const SoftTissueModelInfo& model_info(SoftTissueModel model) {
  for (const auto& m : kModels)
    if (m.model == model) return m;
  return kModels.front();  // unreachable: every enumerator has its entry
}

ModelSolution solve_model(SoftTissueModel model, const TetMesh& mesh, const BoundaryConditions& bc,
                          const ModelSolveOptions& options) {
  return model_info(model).solve(mesh, bc, options);
}

std::string_view model_name(SoftTissueModel model) { return model_info(model).name; }

std::string_view model_title(SoftTissueModel model) { return model_info(model).title; }

std::optional<SoftTissueModel> parse_model(std::string_view name) {
  for (const auto& m : kModels)
    if (m.name == name) return m.model;
  return std::nullopt;
}

std::vector<std::string> model_names() {
  std::vector<std::string> names;
  for (const auto& m : kModels) names.emplace_back(m.name);
  return names;
}

std::string model_choices() {
  std::string text;
  for (size_t i = 0; i < kModels.size(); ++i) {
    if (i > 0) text += i + 1 == kModels.size() ? " or " : ", ";
    text += std::string(kModels[i].name) + " (" + std::string(kModels[i].title) + ")";
  }
  return text;
}

}  // namespace maxillo::softtissue
