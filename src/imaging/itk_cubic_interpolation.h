#pragma once
// Internal to itk_registration.cpp (the one translation unit that includes it, so ITK stays in
// one unit): the moving CT as a cubic B-spline, its value and its gradient from the same
// coefficients, for the Mattes metric.
//
// Why not ITK's defaults: with linear interpolation the metric is a sum of ~14,000 piecewise
// linear terms, and the metric's gradient (central differences a voxel either side) is not the
// gradient of the values the line search compares. The optimiser then ends wherever the two
// stop agreeing: nudging the moving CT's origin by 1e-7 mm moved the answer on the cadaver head
// by 0.010 deg. The cubic B-spline is twice differentiable and its exact gradient goes with it,
// so the minimum is a point the optimiser can reach (with the rest of this set-up, the same
// nudge moves the answer by less than 1e-8 deg). ITK's BSplineInterpolateImageFunction
// allocates its weights on the heap at every call; this evaluates them on the stack, in one
// pass over the 4 x 4 x 4 coefficients.
//
// Values are clamped to [low, high] (the metric's histogram range; the clamped image's spline
// overshoots a little at sharp edges): the gradient is zero where the value is clamped, so the
// two stay consistent.
#include <itkBSplineDecompositionImageFilter.h>
#include <itkCovariantVector.h>
#include <itkImage.h>
#include <itkImageFunction.h>
#include <itkInterpolateImageFunction.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace maxillo::itk_registration {

// The moving CT in double: the metric keeps the interpolated value in the image's pixel type,
// and float's rounding of it (~1e-4 HU) was noise in the metric (~1e-8) that stalled the
// optimiser short of the optimum. The coefficients may be float: they are constants.
using MovingImage = itk::Image<double, 3>;
using CoefficientImage = itk::Image<float, 3>;
using Gradient = itk::CovariantVector<double, 3>;

// Cubic B-spline weights of the 4 nodes floor(x) - 1 ... floor(x) + 2 at offset t = x - floor(x),
// and their derivatives.
struct CubicWeights {
  std::array<double, 4> w, dw;
  explicit CubicWeights(double t) {
    const double s = 1 - t, t2 = t * t;
    w = {s * s * s / 6, (3 * t2 * t - 6 * t2 + 4) / 6, (-3 * t2 * t + 3 * t2 + 3 * t + 1) / 6, t2 * t / 6};
    dw = {-s * s / 2, 1.5 * t2 - 2 * t, -1.5 * t2 + t + 0.5, t2 / 2};
  }
};

class CubicInterpolator : public itk::InterpolateImageFunction<MovingImage, double> {
 public:
  using Self = CubicInterpolator;
  using Superclass = itk::InterpolateImageFunction<MovingImage, double>;
  using Pointer = itk::SmartPointer<Self>;
  using ConstPointer = itk::SmartPointer<const Self>;
  itkNewMacro(Self) itkTypeMacro(CubicInterpolator, InterpolateImageFunction)

      void SetRange(double low, double high) {
    low_ = low;
    high_ = high;
  }

  // The metric sets its moving image here (once per level): the spline coefficients are
  // computed then, when the image is a new one.
  void SetInputImage(const MovingImage* image) override {
    if (image != this->GetInputImage() || !coefficients_) {
      auto decomposition = itk::BSplineDecompositionImageFilter<MovingImage, CoefficientImage>::New();
      decomposition->SetSplineOrder(3);
      decomposition->SetInput(image);
      decomposition->Update();
      coefficients_ = decomposition->GetOutput();
      for (int a = 0; a < 3; ++a) size_[size_t(a)] = long(image->GetLargestPossibleRegion().GetSize()[a]);
      // d value / d LPS = direction * spacing^-1 * d value / d index
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) index_to_lps_(r, c) = image->GetDirection()(r, c) / image->GetSpacing()[c];
    }
    Superclass::SetInputImage(image);
  }

  OutputType EvaluateAtContinuousIndex(const ContinuousIndexType& x) const override {
    double value = 0;
    evaluate(x, value, nullptr);
    return value;
  }

  // Value and gradient (per mm, LPS) at an LPS point; the gradient is zero where the value is clamped.
  Gradient GradientAt(const PointType& point) const {
    ContinuousIndexType x;
    this->GetInputImage()->TransformPhysicalPointToContinuousIndex(point, x);
    double value = 0;
    std::array<double, 3> by_index{};
    evaluate(x, value, &by_index);
    Gradient gradient;
    for (int r = 0; r < 3; ++r)
      gradient[r] =
          index_to_lps_(r, 0) * by_index[0] + index_to_lps_(r, 1) * by_index[1] + index_to_lps_(r, 2) * by_index[2];
    return gradient;
  }

  SizeType GetRadius() const override {
    SizeType radius;
    radius.Fill(2);
    return radius;
  }

 protected:
  CubicInterpolator() = default;

 private:
  // Nodes beyond the image repeat its edge coefficients (samples are kept two voxels inside).
  void evaluate(const ContinuousIndexType& x, double& value, std::array<double, 3>* by_index) const {
    std::array<std::array<long, 4>, 3> node{};
    std::array<CubicWeights, 3> weights{CubicWeights(0), CubicWeights(0), CubicWeights(0)};
    for (int a = 0; a < 3; ++a) {
      const double base = std::floor(x[a]);
      weights[size_t(a)] = CubicWeights(x[a] - base);
      for (int n = 0; n < 4; ++n) node[size_t(a)][size_t(n)] = std::clamp(long(base) - 1 + n, 0L, size_[size_t(a)] - 1);
    }
    const float* c = coefficients_->GetBufferPointer();
    const long nx = size_[0], nxy = size_[0] * size_[1];
    double v = 0, gx = 0, gy = 0, gz = 0;
    for (size_t k = 0; k < 4; ++k) {
      const double wz = weights[2].w[k], dz = weights[2].dw[k];
      for (size_t j = 0; j < 4; ++j) {
        const float* row = c + node[2][k] * nxy + node[1][j] * nx;
        double rv = 0, rdx = 0;
        for (size_t i = 0; i < 4; ++i) {
          const double coefficient = row[node[0][i]];
          rv += weights[0].w[i] * coefficient;
          rdx += weights[0].dw[i] * coefficient;
        }
        const double wy = weights[1].w[j], dy = weights[1].dw[j];
        v += wz * wy * rv;
        gx += wz * wy * rdx;
        gy += wz * dy * rv;
        gz += dz * wy * rv;
      }
    }
    value = std::clamp(v, low_, high_);
    if (by_index) *by_index = (v < low_ || v > high_) ? std::array<double, 3>{} : std::array<double, 3>{gx, gy, gz};
  }

  CoefficientImage::Pointer coefficients_;
  std::array<long, 3> size_{};
  itk::Matrix<double, 3, 3> index_to_lps_;
  double low_ = -1e30, high_ = 1e30;
};

// The metric asks a separate image function for the moving image's gradient: this one answers
// from the interpolator's spline.
class CubicGradient : public itk::ImageFunction<MovingImage, Gradient, double> {
 public:
  using Self = CubicGradient;
  using Superclass = itk::ImageFunction<MovingImage, Gradient, double>;
  using Pointer = itk::SmartPointer<Self>;
  itkNewMacro(Self) itkTypeMacro(CubicGradient, ImageFunction)

      void SetInterpolator(const CubicInterpolator* interpolator) {
    interpolator_ = interpolator;
  }

  OutputType Evaluate(const PointType& point) const override { return interpolator_->GradientAt(point); }
  OutputType EvaluateAtIndex(const IndexType& index) const override {
    PointType point;
    this->GetInputImage()->TransformIndexToPhysicalPoint(index, point);
    return Evaluate(point);
  }
  OutputType EvaluateAtContinuousIndex(const ContinuousIndexType& index) const override {
    PointType point;
    this->GetInputImage()->TransformContinuousIndexToPhysicalPoint(index, point);
    return Evaluate(point);
  }

 protected:
  CubicGradient() = default;

 private:
  CubicInterpolator::ConstPointer interpolator_;
};

}  // namespace maxillo::itk_registration
