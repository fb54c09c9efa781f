// Rigid Mattes mutual-information registration with ITK v4 (see itk_registration.h). ITK only:
// no Eigen, no maxillo types beyond Error.
//
// Set-up (tuned on the real cadaver head, see `maxillo bench register`):
//   VersorRigid3DTransform about the centre given by the caller; both CTs clamped to the
//   histogram range; a pyramid of 2x2x2 block means built here once (cheaper than
//   ImageRegistrationMethodv4's own levels, which smooth the full-size moving image again at every
//   level); each shrunk level is one ImageRegistrationMethodv4 run with conjugate gradients and a
//   golden-section line search, parameter scales from the physical shift of the fixed domain's
//   corners, a first step of at most half the level's voxel, and a convergence window on the
//   metric; the full-resolution level is minimised by BFGS until the transform stands still
//   (itk_quasi_newton.h). The metric: Mattes mutual information summed in a fixed order over a
//   fixed range (itk_ordered_mattes.h) at the caller's samples (registration_samples.h) that stay
//   inside the moving CT, the moving CT as a cubic B-spline with its exact gradient
//   (itk_cubic_interpolation.h). One answer for the same inputs, whatever the threads do, and
//   the optimum of the metric rather than where an optimiser slowed down.
#include "imaging/itk_registration.h"

#include <itkCommand.h>
#include <itkConjugateGradientLineSearchOptimizerv4.h>
#include <itkImage.h>
#include <itkImageRegistrationMethodv4.h>
#include <itkMultiThreaderBase.h>
#include <itkRegistrationParameterScalesFromPhysicalShift.h>
#include <itkVersorRigid3DTransform.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "core/log.h"
#include "imaging/itk_cubic_interpolation.h"
#include "imaging/itk_ordered_mattes.h"
#include "imaging/itk_quasi_newton.h"

namespace maxillo::itk_registration {
namespace {

using Transform = itk::VersorRigid3DTransform<double>;
using FixedImage = itk::Image<float, 3>;
using Metric = OrderedMattesMetric<FixedImage, MovingImage>;
using SamplePoints = Metric::FixedSampledPointSetType;
using Scales = itk::RegistrationParameterScalesFromPhysicalShift<Metric>;

template <typename ItkImage>
void place(ItkImage* image, const itk_filters::Grid& grid, const std::array<double, 3>& origin,
           const std::array<double, 9>& direction) {
  typename ItkImage::SizeType size{{grid.size[0], grid.size[1], grid.size[2]}};
  image->SetRegions(typename ItkImage::RegionType(size));
  typename ItkImage::SpacingType spacing;
  typename ItkImage::PointType itk_origin;
  typename ItkImage::DirectionType itk_direction;
  for (int r = 0; r < 3; ++r) {
    spacing[r] = grid.spacing[size_t(r)];
    itk_origin[r] = origin[size_t(r)];
    for (int c = 0; c < 3; ++c) itk_direction(r, c) = direction[size_t(3 * r + c)];
  }
  image->SetSpacing(spacing);
  image->SetOrigin(itk_origin);
  image->SetDirection(itk_direction);
  image->Allocate();
}

// The CT clamped to [low, high] (the histograms' range).
template <typename ItkImage>
typename ItkImage::Pointer to_itk_image(const Image& source, double low, double high) {
  auto image = ItkImage::New();
  place(image.GetPointer(), source.grid, source.origin, source.direction);
  const size_t count = source.grid.size[0] * source.grid.size[1] * source.grid.size[2];
  std::transform(source.hu, source.hu + count, image->GetBufferPointer(),
                 [=](int16_t hu) { return typename ItkImage::PixelType(std::clamp(double(hu), low, high)); });
  return image;
}

Transform::Pointer to_transform(const RigidMap& map) {
  auto transform = Transform::New();
  Transform::InputPointType centre;
  Transform::MatrixType matrix;
  Transform::OutputVectorType translation;
  for (int r = 0; r < 3; ++r) {
    centre[r] = map.centre[size_t(r)];
    translation[r] = map.translation[size_t(r)];
    for (int c = 0; c < 3; ++c) matrix(r, c) = map.matrix[size_t(3 * r + c)];
  }
  transform->SetCenter(centre);
  transform->SetMatrix(matrix, 1e-6);
  transform->SetTranslation(translation);
  return transform;
}

RigidMap from_transform(const Transform& transform) {
  RigidMap map;
  for (int r = 0; r < 3; ++r) {
    map.centre[size_t(r)] = transform.GetCenter()[r];
    map.translation[size_t(r)] = transform.GetTranslation()[r];
    for (int c = 0; c < 3; ++c) map.matrix[size_t(3 * r + c)] = transform.GetMatrix()(r, c);
  }
  return map;
}

using Optimizer = itk::ConjugateGradientLineSearchOptimizerv4Template<double>;
using Method = itk::ImageRegistrationMethodv4<FixedImage, MovingImage, Transform>;

// Counts the optimiser's iterations.
class IterationCounter : public itk::Command {
 public:
  using Self = IterationCounter;
  using Pointer = itk::SmartPointer<Self>;
  itkNewMacro(Self) int iterations = 0;
  void Execute(itk::Object*, const itk::EventObject&) override { ++iterations; }
  void Execute(const itk::Object*, const itk::EventObject&) override { ++iterations; }
};

// The pyramid: each level halves the previous one by averaging 2 x 2 x 2 blocks (the block
// mean is the smoothing). Doing it here, once, rather than through ImageRegistrationMethodv4's
// own levels saves its Gaussian smoothing of the full-size moving image at every level, which
// cost more than the optimisation itself on a 256 x 256 x 113 head.
template <typename ItkImage>
typename ItkImage::Pointer halved(const ItkImage* image) {
  const auto size = image->GetLargestPossibleRegion().GetSize();
  typename ItkImage::SizeType half;
  for (int a = 0; a < 3; ++a) half[a] = std::max<itk::SizeValueType>(1, size[a] / 2);
  auto out = ItkImage::New();
  out->SetRegions(typename ItkImage::RegionType(half));
  typename ItkImage::SpacingType spacing = image->GetSpacing() * 2.0;
  out->SetSpacing(spacing);
  out->SetDirection(image->GetDirection());
  // Voxel (0,0,0) of the result is the centre of the first block: half a source voxel further.
  typename ItkImage::PointType origin;
  itk::ContinuousIndex<double, 3> block_centre;
  block_centre.Fill(0.5);
  image->TransformContinuousIndexToPhysicalPoint(block_centre, origin);
  out->SetOrigin(origin);
  out->Allocate();
  using Pixel = typename ItkImage::PixelType;
  const Pixel* in = image->GetBufferPointer();
  Pixel* o = out->GetBufferPointer();
  const size_t nx = size[0], nxy = size[0] * size[1];
  for (size_t k = 0; k < half[2]; ++k)
    for (size_t j = 0; j < half[1]; ++j)
      for (size_t i = 0; i < half[0]; ++i) {
        Pixel sum = 0;
        int count = 0;
        for (size_t dk = 0; dk < 2; ++dk)
          for (size_t dj = 0; dj < 2; ++dj)
            for (size_t di = 0; di < 2; ++di) {
              const size_t si = 2 * i + di, sj = 2 * j + dj, sk = 2 * k + dk;
              if (si >= size[0] || sj >= size[1] || sk >= size[2]) continue;
              sum += in[si + nx * sj + nxy * sk];
              ++count;
            }
        o[i + half[0] * (j + half[1] * k)] = sum / Pixel(count);
      }
  return out;
}

// The samples whose image under `transform` lies at least kMarginVoxels inside `moving`, in
// their given order. A sample that left the moving CT during the level would drop out of the
// histogram: a jump in the metric that the line search chases (the answer then depended on
// which samples happened to cross the edge: on the cadaver head, whose vertex the 4 degree move
// takes out of the image, hundreds did). The margin covers the spline's reach and the level's
// motion.
constexpr double kMarginVoxels = 2;
Samples samples_inside(const Samples& samples, const MovingImage& moving, const Transform& transform) {
  const auto size = moving.GetLargestPossibleRegion().GetSize();
  Samples inside;
  for (const auto& sample : samples) {
    Transform::InputPointType point(sample.data());
    itk::ContinuousIndex<double, 3> index;
    moving.TransformPhysicalPointToContinuousIndex(transform.TransformPoint(point), index);
    bool within = true;
    for (int a = 0; a < 3; ++a)
      within = within && index[a] >= kMarginVoxels - 0.5 && index[a] <= double(size[a]) - 0.5 - kMarginVoxels;
    if (within) inside.push_back(sample);
  }
  return inside;
}

SamplePoints::Pointer to_point_set(const Samples& samples) {
  auto points = SamplePoints::New();
  points->Initialize();
  for (size_t n = 0; n < samples.size(); ++n) {
    SamplePoints::PointType point;
    for (int a = 0; a < 3; ++a) point[a] = float(samples[n][size_t(a)]);
    points->SetPoint(itk::IdentifierType(n), point);
  }
  return points;
}

struct LevelOutcome {
  int iterations = 0;
  double metric = 0;
  bool converged = true;
};

// Mattes mutual information at the samples, the moving CT as a cubic spline (its coefficients
// are computed once per level, by the interpolator, when the metric is initialised).
Metric::Pointer mattes_metric(CubicInterpolator* interpolator, const Samples& samples, const Settings& settings) {
  auto metric = Metric::New();
  metric->SetNumberOfHistogramBins(settings.histogram_bins);
  metric->SetIntensityRange(settings.low, settings.high);
  auto gradient = CubicGradient::New();
  gradient->SetInterpolator(interpolator);
  metric->SetMovingInterpolator(interpolator);
  metric->SetMovingImageGradientCalculator(gradient);
  metric->SetUseMovingImageGradientFilter(false);
  metric->SetUseFixedImageGradientFilter(false);
  metric->SetFixedSampledPointSet(to_point_set(samples));
  metric->SetUseSampledPointSet(true);
  return metric;
}

// A shrunk level: conjugate gradients with a golden-section line search along each direction
// (the default box, the cranium, is nearly a sphere: rotations about its centre change the
// metric little, a long narrow valley across which plain or regular-step gradient descent
// zig-zags and stops short; conjugate directions follow it). The first step moves the image by
// at most half a voxel of the level; the level ends when the metric's normalised slope over the
// last `window` iterations falls below coarse_convergence: it only needs to get close.
LevelOutcome register_shrunk_level(FixedImage* fixed, MovingImage* moving, CubicInterpolator* interpolator,
                                   const Samples& samples, Transform* transform, const Settings& settings) {
  auto metric = mattes_metric(interpolator, samples, settings);
  auto scales = Scales::New();
  scales->SetMetric(metric);
  scales->SetTransformForward(true);
  auto optimizer = Optimizer::New();
  optimizer->SetScalesEstimator(scales);
  const auto spacing = fixed->GetSpacing();
  optimizer->SetMaximumStepSizeInPhysicalUnits(0.5 * std::min({spacing[0], spacing[1], spacing[2]}));
  optimizer->SetDoEstimateLearningRateOnce(true);
  optimizer->SetDoEstimateLearningRateAtEachIteration(false);
  optimizer->SetLowerLimit(0);
  optimizer->SetUpperLimit(2);
  optimizer->SetEpsilon(0.05);
  optimizer->SetMaximumLineSearchIterations(6);
  optimizer->SetMinimumConvergenceValue(settings.coarse_convergence);
  optimizer->SetConvergenceWindowSize(itk::SizeValueType(std::max(3, settings.window)));
  optimizer->SetNumberOfIterations(itk::SizeValueType(std::max(1, settings.max_iterations_per_level)));
  auto counter = IterationCounter::New();
  optimizer->AddObserver(itk::IterationEvent(), counter);

  auto method = Method::New();
  method->SetFixedImage(fixed);
  method->SetMovingImage(moving);
  method->SetMetric(metric);
  method->SetOptimizer(optimizer);
  method->SetInitialTransform(transform);
  method->InPlaceOn();
  Method::ShrinkFactorsArrayType shrink(1);
  shrink.Fill(1);
  Method::SmoothingSigmasArrayType sigmas(1);
  sigmas.Fill(0);
  method->SetNumberOfLevels(1);
  method->SetShrinkFactorsPerLevel(shrink);
  method->SetSmoothingSigmasPerLevel(sigmas);
  method->SetMetricSamplingStrategy(Method::MetricSamplingStrategyEnum::NONE);  // the metric's own samples
  try {
    method->Update();
  } catch (const itk::ExceptionObject& e) {
    throw Error(ErrorCode::kProcessing, "registration", std::string("ITK registration failed: ") + e.GetDescription());
  }
  log::debug("registration level with ", spacing[0], " x ", spacing[1], " x ", spacing[2],
             " mm voxels: ", counter->iterations, " iterations, metric ", optimizer->GetValue(), "; ",
             optimizer->GetStopConditionDescription());
  return {counter->iterations, optimizer->GetValue(), true};
}

// BFGS (itk_quasi_newton.h) at full resolution from the transform as it is until it stands
// still; the first step moves the image by at most half a voxel (inverse_hessian: see
// minimise_by_bfgs).
LevelOutcome minimise_at_full_resolution(FixedImage* fixed, MovingImage* moving, CubicInterpolator* interpolator,
                                         const Samples& samples, Transform* transform, const Settings& settings,
                                         std::vector<double>& inverse_hessian) {
  auto metric = mattes_metric(interpolator, samples, settings);
  metric->SetFixedImage(fixed);
  metric->SetMovingImage(moving);
  metric->SetMovingTransform(transform);
  auto scales = Scales::New();
  scales->SetMetric(metric);
  scales->SetTransformForward(true);
  const auto spacing = fixed->GetSpacing();
  const double half_voxel = 0.5 * std::min({spacing[0], spacing[1], spacing[2]});
  QuasiNewtonOutcome done;
  try {
    metric->Initialize();
    done = minimise_by_bfgs(*metric, *scales,
                            {.first_step_mm = half_voxel,
                             .max_step_mm = 2 * half_voxel,
                             .still_mm = settings.fine_step_mm,
                             .window = settings.window,
                             .max_iterations = settings.max_iterations_per_level},
                            inverse_hessian);
  } catch (const itk::ExceptionObject& e) {
    throw Error(ErrorCode::kProcessing, "registration", std::string("ITK registration failed: ") + e.GetDescription());
  }
  log::debug("registration, full resolution: ", done.iterations, " iterations, metric ", done.value,
             done.converged ? "" : ", not converged");
  return {done.iterations, done.value, done.converged};
}

// The full-resolution level. Which samples stay inside the moving CT depends on where the level
// starts, and with them the optimum (a 1e-7 mm nudge of the start changed 5 of 14,000 samples on
// the cadaver head, and the answer by 0.0005 deg). So the level runs again from its answer with
// the samples inside there, until that set no longer changes (usually once more, a few
// iterations): the samples then follow from the answer, not from the path to it.
constexpr int kMaxSampleRounds = 4;
LevelOutcome register_full_resolution(FixedImage* fixed, MovingImage* moving, const Samples& samples,
                                      Transform* transform, const Settings& settings) {
  auto interpolator = CubicInterpolator::New();  // its spline is computed once, for all rounds
  interpolator->SetRange(settings.low, settings.high);
  std::vector<double> inverse_hessian;  // carried from round to round: the optimum barely moves
  Samples used = samples_inside(samples, *moving, *transform);
  LevelOutcome outcome;
  for (int round = 0; round < kMaxSampleRounds; ++round) {
    const LevelOutcome done =
        minimise_at_full_resolution(fixed, moving, interpolator, used, transform, settings, inverse_hessian);
    outcome = {outcome.iterations + done.iterations, done.metric, done.converged};
    Samples at_answer = samples_inside(samples, *moving, *transform);
    log::debug("registration, full resolution, round ", round + 1, ": ", used.size(), " samples, ", at_answer.size(),
               " inside at its answer", at_answer == used ? " (the same)" : "");
    if (!done.converged || at_answer == used) break;
    used = std::move(at_answer);
  }
  return outcome;
}

// ITK's global default thread count limited for one registration (0: left as it is), restored
// after: every ITK object made meanwhile takes its thread count from it.
class ThreadLimit {
 public:
  explicit ThreadLimit(int threads) : previous_(itk::MultiThreaderBase::GetGlobalDefaultNumberOfThreads()) {
    if (threads > 0) itk::MultiThreaderBase::SetGlobalDefaultNumberOfThreads(itk::ThreadIdType(threads));
  }
  ~ThreadLimit() { itk::MultiThreaderBase::SetGlobalDefaultNumberOfThreads(previous_); }
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

 private:
  itk::ThreadIdType previous_;
};

}  // namespace

Outcome register_rigid(const Image& fixed, const Image& moving, const Settings& settings) {
  const ThreadLimit limit(settings.threads);
  const int levels = int(settings.samples.size());
  assert(levels > 0 && "register_rigid: settings.samples needs one sample list per pyramid level");
  std::vector<FixedImage::Pointer> fixed_pyramid{to_itk_image<FixedImage>(fixed, settings.low, settings.high)};
  std::vector<MovingImage::Pointer> moving_pyramid{to_itk_image<MovingImage>(moving, settings.low, settings.high)};
  for (int level = 1; level < levels; ++level) {
    fixed_pyramid.push_back(halved(fixed_pyramid.back().GetPointer()));
    moving_pyramid.push_back(halved(moving_pyramid.back().GetPointer()));
  }
  Transform::Pointer transform = to_transform(settings.initial);

  Outcome outcome;
  for (int level = levels - 1; level > 0; --level) {
    auto interpolator = CubicInterpolator::New();
    interpolator->SetRange(settings.low, settings.high);
    MovingImage* moving_level = moving_pyramid[size_t(level)];
    const Samples inside = samples_inside(settings.samples[size_t(level)], *moving_level, *transform);
    outcome.iterations +=
        register_shrunk_level(fixed_pyramid[size_t(level)], moving_level, interpolator, inside, transform, settings)
            .iterations;
  }
  const LevelOutcome finest = register_full_resolution(fixed_pyramid.front(), moving_pyramid.front(),
                                                       settings.samples.front(), transform, settings);
  outcome.iterations += finest.iterations;
  outcome.metric = finest.metric;
  outcome.converged = finest.converged;
  outcome.fixed_to_moving = from_transform(*transform);
  return outcome;
}

}  // namespace maxillo::itk_registration
