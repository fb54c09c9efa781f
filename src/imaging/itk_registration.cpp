// Rigid Mattes mutual-information registration with ITK v4 (see itk_registration.h). ITK only:
// no Eigen, no maxillo types beyond Error.
//
// Set-up (tuned on the real cadaver head, see `maxillo bench register`):
//   VersorRigid3DTransform about the centre given by the caller; a pyramid of 2x2x2 block means
//   built here once (cheaper than ImageRegistrationMethodv4's own levels, which smooth the
//   full-size moving image again at every level); each level is one ImageRegistrationMethodv4 run
//   with conjugate gradients and a golden-section line search, parameter scales from the physical
//   shift of the fixed domain's corners, a first step of at most half the level's voxel, and a
//   convergence window on the metric; samples: a jittered regular subset per level (seeded) kept
//   inside the fixed mask; moving-image gradients by central differences at the samples rather
//   than a gradient image of the whole volume (the samples only ever look at a fraction of it).
#include "imaging/itk_registration.h"

#include <itkCommand.h>
#include <itkConjugateGradientLineSearchOptimizerv4.h>
#include <itkImage.h>
#include <itkImageMaskSpatialObject.h>
#include <itkImageRegistrationMethodv4.h>
#include <itkMattesMutualInformationImageToImageMetricv4.h>
#include <itkMultiThreaderBase.h>
#include <itkRegistrationParameterScalesFromPhysicalShift.h>
#include <itkVersorRigid3DTransform.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <vector>

#include "core/error.h"
#include "core/log.h"

namespace maxillo::itk_registration {
namespace {

using FloatImage = itk::Image<float, 3>;
using MaskImage = itk::Image<uint8_t, 3>;
using MaskObject = itk::ImageMaskSpatialObject<3>;
using Transform = itk::VersorRigid3DTransform<double>;
using Metric = itk::MattesMutualInformationImageToImageMetricv4<FloatImage, FloatImage>;
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

FloatImage::Pointer to_float_image(const Image& source) {
  auto image = FloatImage::New();
  place(image.GetPointer(), source.grid, source.origin, source.direction);
  const size_t count = source.grid.size[0] * source.grid.size[1] * source.grid.size[2];
  std::copy(source.hu, source.hu + count, image->GetBufferPointer());
  return image;
}

MaskObject::Pointer to_mask_object(const itk_filters::Mask& mask, const Image& fixed) {
  auto image = MaskImage::New();
  place(image.GetPointer(), fixed.grid, fixed.origin, fixed.direction);
  std::memcpy(image->GetBufferPointer(), mask.data(), mask.size());
  auto object = MaskObject::New();
  object->SetImage(image);
  object->Update();
  return object;
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
using Method = itk::ImageRegistrationMethodv4<FloatImage, FloatImage, Transform>;

using Optimizer = itk::ConjugateGradientLineSearchOptimizerv4Template<double>;
using Method = itk::ImageRegistrationMethodv4<FloatImage, FloatImage, Transform>;

// Counts the optimiser's iterations.
class IterationCounter : public itk::Command {
 public:
  using Self = IterationCounter;
  using Pointer = itk::SmartPointer<Self>;
  itkNewMacro(Self)
  int iterations = 0;
  void Execute(itk::Object*, const itk::EventObject&) override { ++iterations; }
  void Execute(const itk::Object*, const itk::EventObject&) override { ++iterations; }
};

// The pyramid: each level halves the previous one by averaging 2 x 2 x 2 blocks (the block
// mean is the smoothing). Doing it here, once, rather than through ImageRegistrationMethodv4's
// own levels saves its Gaussian smoothing of the full-size moving image at every level, which
// cost more than the optimisation itself on a 256 x 256 x 113 head.
FloatImage::Pointer halved(const FloatImage* image) {
  const auto size = image->GetLargestPossibleRegion().GetSize();
  FloatImage::SizeType half;
  for (int a = 0; a < 3; ++a) half[a] = std::max<itk::SizeValueType>(1, size[a] / 2);
  auto out = FloatImage::New();
  out->SetRegions(FloatImage::RegionType(half));
  FloatImage::SpacingType spacing = image->GetSpacing() * 2.0;
  out->SetSpacing(spacing);
  out->SetDirection(image->GetDirection());
  // Voxel (0,0,0) of the result is the centre of the first block: half a source voxel further.
  FloatImage::PointType origin;
  itk::ContinuousIndex<double, 3> block_centre;
  block_centre.Fill(0.5);
  image->TransformContinuousIndexToPhysicalPoint(block_centre, origin);
  out->SetOrigin(origin);
  out->Allocate();
  const float* in = image->GetBufferPointer();
  float* o = out->GetBufferPointer();
  const size_t nx = size[0], nxy = size[0] * size[1];
  for (size_t k = 0; k < half[2]; ++k)
    for (size_t j = 0; j < half[1]; ++j)
      for (size_t i = 0; i < half[0]; ++i) {
        float sum = 0;
        int count = 0;
        for (size_t dk = 0; dk < 2; ++dk)
          for (size_t dj = 0; dj < 2; ++dj)
            for (size_t di = 0; di < 2; ++di) {
              const size_t si = 2 * i + di, sj = 2 * j + dj, sk = 2 * k + dk;
              if (si >= size[0] || sj >= size[1] || sk >= size[2]) continue;
              sum += in[si + nx * sj + nxy * sk];
              ++count;
            }
        o[i + half[0] * (j + half[1] * k)] = sum / float(count);
      }
  return out;
}

struct LevelOutcome {
  int iterations = 0;
  double metric = 0;
};

// One level: conjugate gradients with a golden-section line search along each direction (the
// default box, the cranium, is nearly a sphere: rotations about its centre change the metric
// little, a long narrow valley across which plain or regular-step gradient descent zig-zags and
// stops short; conjugate directions follow it). The first step moves the image by at most half
// a voxel of the level; the level ends when the metric's normalised slope over the last
// `window` iterations falls below `convergence`.
LevelOutcome register_level(FloatImage* fixed, FloatImage* moving, MaskObject* mask, Transform* transform,
                            const Settings& settings, double sampling, double convergence, uint32_t seed) {
  auto metric = Metric::New();
  metric->SetNumberOfHistogramBins(settings.histogram_bins);
  metric->SetUseMovingImageGradientFilter(false);
  metric->SetUseFixedImageGradientFilter(false);
  if (mask) metric->SetFixedImageMask(mask);

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
  optimizer->SetMinimumConvergenceValue(convergence);
  optimizer->SetConvergenceWindowSize(itk::SizeValueType(std::max(3, settings.fine_window)));
  optimizer->SetNumberOfIterations(itk::SizeValueType(std::max(1, settings.max_iterations_per_level)));

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
  Method::MetricSamplingPercentageArrayType percentage(1);
  percentage.Fill(std::clamp(sampling, 1e-4, 1.0));
  method->SetNumberOfLevels(1);
  method->SetShrinkFactorsPerLevel(shrink);
  method->SetSmoothingSigmasPerLevel(sigmas);
  method->SetMetricSamplingStrategy(settings.regular_sampling ? Method::MetricSamplingStrategyEnum::REGULAR
                                                              : Method::MetricSamplingStrategyEnum::RANDOM);
  method->SetMetricSamplingPercentagePerLevel(percentage);
  method->MetricSamplingReinitializeSeed(int(seed));
  auto counter = IterationCounter::New();
  optimizer->AddObserver(itk::IterationEvent(), counter);
  try {
    method->Update();
  } catch (const itk::ExceptionObject& e) {
    throw Error(ErrorCode::kProcessing, "registration", std::string("ITK registration failed: ") + e.GetDescription());
  }
  log::debug("registration level with ", spacing[0], " x ", spacing[1], " x ", spacing[2], " mm voxels: ",
             counter->iterations, " iterations, metric ", optimizer->GetValue(), "; ",
             optimizer->GetStopConditionDescription());
  return {counter->iterations, optimizer->GetValue()};
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
  const int levels = std::max(1, settings.levels);
  std::vector<FloatImage::Pointer> fixed_pyramid{to_float_image(fixed)}, moving_pyramid{to_float_image(moving)};
  for (int level = 1; level < levels; ++level) {
    fixed_pyramid.push_back(halved(fixed_pyramid.back()));
    moving_pyramid.push_back(halved(moving_pyramid.back()));
  }
  MaskObject::Pointer mask = settings.fixed_mask ? to_mask_object(*settings.fixed_mask, fixed) : nullptr;
  Transform::Pointer transform = to_transform(settings.initial);

  Outcome outcome;
  for (int level = levels - 1; level >= 0; --level) {
    // A level shrunk by f has f^3 fewer voxels; sampling f^2 times the fraction keeps a half
    // (f = 2) or a quarter (f = 4) as many samples as full resolution: a few hundred samples
    // would fill the 50-bin joint histogram too thinly to steer.
    const double factor = std::pow(2.0, level);
    const bool finest = level == 0;
    const LevelOutcome done =
        register_level(fixed_pyramid[size_t(level)], moving_pyramid[size_t(level)], mask, transform, settings,
                       settings.sampling_fraction * factor * factor,
                       finest ? settings.fine_convergence : settings.coarse_convergence, settings.seed + uint32_t(level));
    outcome.iterations += done.iterations;
    outcome.last_level_iterations = done.iterations;
    outcome.metric = done.metric;
  }
  outcome.fixed_to_moving = from_transform(*transform);
  return outcome;
}

}  // namespace maxillo::itk_registration
