#pragma once
// How each soft tissue model solves the static problem of a face (or any tet mesh): its set-up
// (stiffness blocks, springs, nothing for Newton's method) and its solver, with the options and
// the refusals the case workflow has always used. The table of models (soft_tissue_model.h)
// names one of these per model; a new model adds its solver here and its row there.
#include <Eigen/Core>

#include "softtissue/boundary_conditions.h"
#include "softtissue/linear_elasticity.h"
#include "softtissue/tet_mesh.h"

namespace maxillo::softtissue {

struct ModelSolveOptions {
  Material material;
  // The point-wise solvers' (mass tensor, mass-spring) local stop threshold, before it is
  // divided by the mesh's stiffness contrast, and their sweep limit: a model still moving
  // after it is an error, not an answer.
  double gradient_threshold_mm = 1e-3;
  int max_sweeps = 100000;
};

struct ModelSolution {
  Eigen::MatrixX3d displacement;  // n x 3, mm
  int iterations = 0;             // sweeps (MTM, MSM), Krylov iterations (FEM) or Newton steps (non-linear FEM)
  double assembly_seconds = 0;    // the model's set-up; 0 where it is assembled inside every step
};

// Each throws Error(kProcessing), naming the model, when it gives no answer: the local
// iterations still moving at their sweep limit, the conjugate gradient or Newton's method not
// converging.
ModelSolution solve_mass_tensor_model(const TetMesh& mesh, const BoundaryConditions& bc,
                                      const ModelSolveOptions& options);
ModelSolution solve_linear_fem(const TetMesh& mesh, const BoundaryConditions& bc, const ModelSolveOptions& options);
ModelSolution solve_mass_spring_model(const TetMesh& mesh, const BoundaryConditions& bc,
                                      const ModelSolveOptions& options);
ModelSolution solve_nonlinear_fem(const TetMesh& mesh, const BoundaryConditions& bc, const ModelSolveOptions& options);

}  // namespace maxillo::softtissue
