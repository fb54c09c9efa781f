#pragma once
// Corresponding points between a predicted and an actual skin surface (thesis ch. 6, section
// 3.5.1): the closest-point distance underestimates a prediction's error, since a point may slide
// along the surface to its nearest neighbour; a smooth non-rigid registration of the prediction
// onto the outcome finds where each predicted point really went. The source used a TPS-RPM
// variant; this is non-rigid Coherent Point Drift (Myronenko & Song, IEEE PAMI 2010), the same idea
// (a Gaussian mixture centred on the moving points, EM, a smooth regularised displacement field).
//
// The displacement is a Gaussian radial basis field v(y) = sum_k G(y, c_k) w_k with
// G(a, b) = exp(-|a - b|^2 / (2 beta^2)), carried by control points c_k: a grid subsample of the
// moving points every 0.75 beta (a Nystrom restriction of CPD's kernel: the regulariser
// lambda/2 tr(W^T G W) suppresses anything finer anyway). Each M-step then solves a K x K system
// (K control points) instead of CPD's M x M one, and every vertex of the moving surface, not only
// the subsample the registration used, is moved by the same field. Two departures from the paper,
// both against a sideways sliding of one surface along the other: the subsets are evenly spread
// (Poisson-disk) rather than random, and sigma stops shrinking at half the subset's point spacing.
//
// What to expect (tests/validation/coherent_point_drift_test.cpp): the regulariser trades fit for
// smoothness, so a 2 mm bump 8 mm wide is under-fitted at its peak by a few tenths of a mm and
// correspondences on a smooth surface wander by ~0.1 mm; the distances below project each
// correspondence onto the actual surface, which removes the under-fit across the surface.
#include <cstdint>
#include <vector>

#include "core/triangle_mesh.h"

namespace maxillo::validation {

struct CpdOptions {
  double beta_mm = 10;          // width of the Gaussian kernel: how far a displacement spreads
  double lambda = 2;            // smoothness against closeness of fit
  double outlier_weight = 0.1;  // w in [0, 1): share of fixed points explained as outliers
  int max_iterations = 80;
  double tolerance = 1e-5;  // stop when the negative log-likelihood changes by less (relative)
  int max_points = 2500;    // of each set used by the EM (an evenly spread subset, deterministic)
  uint32_t seed = 1;
};

struct CpdResult {
  VertexMatrix moved;  // every vertex of `moving`, displaced by the registration's field
  int iterations = 0;
  double sigma2 = 0;  // final variance of the mixture, mm^2 (the residual misfit's scale)
};

// Registers `moving` non-rigidly onto `fixed` (both in mm, the same frame). Throws Error(BadValue)
// for an empty set or options out of range.
CpdResult nonrigid_cpd(const VertexMatrix& fixed, const VertexMatrix& moving, const CpdOptions& options = {});

// The corresponding-point distance of each predicted vertex (where include[i]; all when empty):
// the distance to its CPD correspondence on `actual` (the registered position projected onto the
// actual surface), signed negative where the prediction lies behind (inside) the actual surface.
// Only actual vertices within max(20 mm, 2 beta) of the included part of `predicted` take part, so
// a whole-head outcome can be compared with a face region. One value per included vertex, in order.
std::vector<double> corresponding_point_distances(const TriangleMesh& predicted, const TriangleMesh& actual,
                                                  const std::vector<bool>& include = {},
                                                  const CpdOptions& options = {});

}  // namespace maxillo::validation
