#pragma once
// `maxillo bench cube`: the thesis' cube test (ch. 6, fig. 2): a cube (100 mm) with its border
// fixed and its centre (20 mm) moved 6 mm upward. Set-up and solve times (median of `runs`),
// iterations and the precision against the fully converged linear FEM answer (tight-tolerance
// conjugate gradient).
// Targets (issue 3, ~105,000 tets): linear FEM <= 0.15 s, mass tensor <= 0.5 s at
// P_min <= 0.3 mm, re-solve after a plan change <= 30 ms.
#include <filesystem>
#include <string>

#include "core/json.h"
#include "softtissue/cube_mesh.h"
#include "softtissue/factorised_elasticity.h"
#include "softtissue/linear_static_solve.h"
#include "softtissue/local_iteration.h"
#include "softtissue/soft_tissue_model.h"

namespace maxillo::bench {

struct CubeBenchOptions {
  int tets = 105000;  // approximate number of tetrahedra
  softtissue::SoftTissueModel model = softtissue::SoftTissueModel::kLinearFem;
  softtissue::HexSplit split = softtissue::HexSplit::kSixTets;
  // fem: the conjugate gradient's preconditioner and relative residual, and the factorisation
  // of the re-solve after a plan change
  softtissue::Preconditioner preconditioner = softtissue::Preconditioner::kBlockJacobi;
  double tolerance = 1e-6;
  softtissue::CholeskyBackend cholesky = softtissue::cholmod_available()
                                             ? softtissue::CholeskyBackend::kCholmodSupernodal
                                             : softtissue::CholeskyBackend::kEigenSimplicial;
  // mtm, msm: the local stop threshold (mm per iteration) and over-relaxation
  softtissue::LocalIterationOptions local{1e-3, 1.0, 1000000};
  int runs = 5;  // timed runs; the median is reported
  // fem: CalculiX (ccx) on the same mesh, material and moves too: its seconds, how far its answer
  // lies from the FEM's, and the ratio of the times (issue 32)
  bool calculix = false;
  std::filesystem::path out;  // when set: the mesh, displacement and bc written as a .vtu file
};

// The figures: the mesh and its boundary conditions (model, tets, nodes, divisions, free_nodes,
// prescribed_nodes, min_dihedral_deg, max_aspect_ratio), assembly_seconds, runs,
// max_displacement_mm, and model_result: the model's own (solve_seconds, iterations, precision
// or difference from FEM in mm; for mtm a threshold_table, one row per stop threshold; with
// calculix: calculix_seconds, calculix_vs_fem_worst_mm, fem_speedup_over_calculix).
Json run_cube_benchmark(const CubeBenchOptions& options);

// The figures as `bench cube` prints them: a "key: value" line each (the model's after the
// mesh's), then mtm's threshold table.
std::string cube_benchmark_text(const Json& figures);

}  // namespace maxillo::bench
