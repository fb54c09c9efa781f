#pragma once
// The soft tissue models a face prediction can use (thesis ch. 6): the mass tensor model, linear
// FEM, the mass-spring model and non-linear (neo-Hookean) FEM. One table holds what the rest of
// the program needs to know of each: its short name for commands and files, its title for
// reports, how it is solved (model_solvers.h), whether the uncertainty band re-solves with it
// and whether `bench face` times it. The commands (`simulate`, `validate`, `bench cube`), the
// case workflow (casework/softtissue/soft_tissue_prediction.h), the uncertainty band and the
// benchmarks read the table, so a new model is one row here and its solver in model_solvers.h.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "softtissue/model_solvers.h"

namespace maxillo::softtissue {

enum class SoftTissueModel { kMassTensor, kLinearFem, kMassSpring, kNonlinearFem };

// Solves the model's static problem on a mesh; throws Error(kProcessing) when it gives no answer.
using ModelSolver = ModelSolution (*)(const TetMesh& mesh, const BoundaryConditions& bc,
                                      const ModelSolveOptions& options);

struct SoftTissueModelInfo {
  SoftTissueModel model;
  std::string_view name;     // "mtm", "fem", "msm", "nfem"
  std::string_view title;    // "mass tensor model", ...
  ModelSolver solve;         // model_solvers.h
  bool in_uncertainty_band;  // re-solved for the uncertainty band (casework/softtissue/case_simulation.h)
  bool in_face_benchmark;    // timed on the phantom's face by `bench face` (bench/face_benchmark.h)
};

// Every model, in the order commands list them.
std::span<const SoftTissueModelInfo> soft_tissue_models();
const SoftTissueModelInfo& model_info(SoftTissueModel model);
// The model's solver from the table.
ModelSolution solve_model(SoftTissueModel model, const TetMesh& mesh, const BoundaryConditions& bc,
                          const ModelSolveOptions& options);

std::string_view model_name(SoftTissueModel model);  // "mtm", "fem", "msm", "nfem"
std::optional<SoftTissueModel> parse_model(std::string_view name);
std::string_view model_title(SoftTissueModel model);  // "mass tensor model", ...
// The names, for a command's check of its --model option.
std::vector<std::string> model_names();
// "mtm (mass tensor model), fem (linear FEM), ... or nfem (...)", for a command's help.
std::string model_choices();

}  // namespace maxillo::softtissue
