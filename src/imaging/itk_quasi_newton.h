#pragma once
// Internal to itk_registration.cpp (the one translation unit that includes it, so ITK stays in
// one unit): the finest level's optimiser, BFGS over the transform's parameters of an ITK v4
// metric, until the transform stands still.
//
// Why not ITK's conjugate gradients there: its golden-section line search is inexact, so the
// directions lose their conjugacy and the last stretch along the cranium's narrow rotation
// valley crept on by 1e-4 to 1e-3 mm per iteration for 20 to 40 iterations (8 metric
// evaluations each), and where it was stopped depended on the path. BFGS learns the valley's
// curvature from the gradients (6 parameters: a 6 x 6 inverse Hessian) and, near the optimum,
// takes the full Newton-like step: 1 to 2 evaluations per iteration, ~15 iterations on the
// cadaver head, and the same answer to ~1e-9 mm from starts 1 deg and 1 mm apart.
//
// Parameters move additively (metric.SetParameters), which is what the metric's derivative is
// taken with respect to (ITK's versor Jacobian is that of the versor's vector part). Steps are
// measured by the scales estimator: the largest shift of the fixed domain's corners, in mm.
#include <itkOptimizerParameters.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace maxillo::itk_registration {

struct QuasiNewtonSettings {
  double first_step_mm = 0.5;  // the first step moves no corner further than this
  double max_step_mm = 2;      // nor does any later one
  double still_mm = 1e-4;      // converged: `window` steps in a row each moved the corners less
  int window = 3;
  int max_iterations = 200;
};

struct QuasiNewtonOutcome {
  int iterations = 0;
  double value = 0;
  bool converged = false;  // false: stopped at max_iterations
};

// `inverse_hessian` (n x n, row-major): empty = start from the scales' diagonal; on return the
// last estimate, to start a nearby minimisation from (the finest level's later rounds).
template <typename TMetric, typename TScalesEstimator>
QuasiNewtonOutcome minimise_by_bfgs(TMetric& metric, TScalesEstimator& scales, const QuasiNewtonSettings& settings,
                                    std::vector<double>& inverse_hessian) {
  using Parameters = typename TMetric::ParametersType;
  using Derivative = typename TMetric::DerivativeType;
  const size_t n = metric.GetNumberOfParameters();
  auto dot = [n](const auto& a, const auto& b) {
    double sum = 0;
    for (size_t i = 0; i < n; ++i) sum += a[i] * b[i];
    return sum;
  };
  // The shift (mm) of the parameters' step p, 0 for none.
  auto shift_mm = [&](const std::vector<double>& p) {
    Parameters step(n);
    for (size_t i = 0; i < n; ++i) step[i] = p[i];
    return double(scales.EstimateStepScale(step));
  };

  Parameters x = metric.GetParameters();
  double f = 0;
  Derivative derivative;
  metric.GetValueAndDerivative(f, derivative);
  std::vector<double> g(n);  // gradient of the value (ITK's derivative points downhill)
  for (size_t i = 0; i < n; ++i) g[i] = -derivative[i];

  // Inverse Hessian, first the scales' diagonal sized so that the first step moves the corners
  // by first_step_mm.
  std::vector<double>& h = inverse_hessian;
  if (h.size() != n * n) {
    typename TScalesEstimator::ScalesType parameter_scales;
    scales.EstimateScales(parameter_scales);
    h.assign(n * n, 0.0);
    std::vector<double> p(n);
    for (size_t i = 0; i < n; ++i) p[i] = g[i] / parameter_scales[i];
    const double shift = shift_mm(p);
    for (size_t i = 0; i < n; ++i) h[i * n + i] = shift > 0 ? settings.first_step_mm / shift / parameter_scales[i] : 0;
  }

  QuasiNewtonOutcome outcome;
  int still = 0;
  std::vector<double> p(n), s(n), y(n), g_new(n), hy(n);
  while (outcome.iterations < settings.max_iterations) {
    ++outcome.iterations;
    for (size_t i = 0; i < n; ++i) {
      p[i] = 0;
      for (size_t j = 0; j < n; ++j) p[i] -= h[i * n + j] * g[j];
    }
    const double slope = dot(g, p);
    if (!(slope < 0)) {  // no descent direction left: the gradient is round-off
      outcome.converged = true;
      break;
    }
    // Backtracking (Armijo) from the full step, capped at max_step_mm.
    const double full_shift = shift_mm(p);
    double t = full_shift > settings.max_step_mm ? settings.max_step_mm / full_shift : 1;
    bool accepted = false;
    double f_new = 0;
    Parameters x_new(n);
    for (int halving = 0; halving < 40 && !accepted; ++halving, t *= 0.5) {
      for (size_t i = 0; i < n; ++i) x_new[i] = x[i] + t * p[i];
      metric.SetParameters(x_new);
      metric.GetValueAndDerivative(f_new, derivative);
      accepted = f_new <= f + 1e-4 * t * slope;
      if (accepted) break;
    }
    if (!accepted) {  // not even a tiny step lowers the metric: the optimum, to round-off
      metric.SetParameters(x);
      outcome.converged = true;
      break;
    }
    for (size_t i = 0; i < n; ++i) {
      g_new[i] = -derivative[i];
      s[i] = x_new[i] - x[i];
      y[i] = g_new[i] - g[i];
    }
    // BFGS update of the inverse Hessian, when the step saw positive curvature.
    const double sy = dot(s, y);
    if (sy > 1e-12 * std::sqrt(dot(s, s) * dot(y, y))) {
      for (size_t i = 0; i < n; ++i) {
        hy[i] = 0;
        for (size_t j = 0; j < n; ++j) hy[i] += h[i * n + j] * y[j];
      }
      const double yhy = dot(y, hy);
      for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < n; ++j)
          h[i * n + j] += ((sy + yhy) * s[i] * s[j]) / (sy * sy) - (hy[i] * s[j] + s[i] * hy[j]) / sy;
    }
    x = x_new;
    f = f_new;
    g = g_new;
    still = shift_mm(s) < settings.still_mm ? still + 1 : 0;
    if (still >= settings.window) {
      outcome.converged = true;
      break;
    }
  }
  outcome.value = f;
  return outcome;
}

}  // namespace maxillo::itk_registration
