#include "softtissue/soft_tissue_model.h"

#include <array>

namespace maxillo::softtissue {
namespace {

struct ModelNames {
  SoftTissueModel model;
  std::string_view name, title;
};
constexpr std::array kModels = {ModelNames{SoftTissueModel::kMassTensor, "mtm", "mass tensor model"},
                                ModelNames{SoftTissueModel::kLinearFem, "fem", "linear FEM"},
                                ModelNames{SoftTissueModel::kMassSpring, "msm", "mass-spring model"},
                                ModelNames{SoftTissueModel::kNonlinearFem, "nfem", "non-linear FEM (neo-Hookean)"}};

}  // namespace

std::string_view model_name(SoftTissueModel model) {
  for (const auto& m : kModels)
    if (m.model == model) return m.name;
  return "?";
}

std::string_view model_title(SoftTissueModel model) {
  for (const auto& m : kModels)
    if (m.model == model) return m.title;
  return "?";
}

std::optional<SoftTissueModel> parse_model(std::string_view name) {
  for (const auto& m : kModels)
    if (m.name == name) return m.model;
  return std::nullopt;
}

}  // namespace maxillo::softtissue
