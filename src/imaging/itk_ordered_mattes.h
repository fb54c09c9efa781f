#pragma once
// Internal to itk_registration.cpp (the one translation unit that includes it, so ITK stays in
// one unit): ITK 5.2's Mattes mutual information with its sums made in a fixed order and its
// histogram over a fixed intensity range, so that the same inputs give the same bits whatever
// the threads do.
//
// Order. ITK splits the samples into work units (contiguous ranges, one joint histogram each,
// added in unit order: deterministic), but for a global transform it adds each unit's
// joint-histogram derivatives into one shared array whenever the unit's buffer fills and it gets
// a try-lock, in whatever order the threads arrive; the sum, and so the optimiser's path,
// changed from run to run (up to 0.011 deg on the cadaver head, 0.1-0.2 deg on a real pre/post
// pair). Here each unit adds into its own array (its own lock, never contended) and the arrays
// are added in unit order after the threads finish. The number of units is fixed (kWorkUnits,
// not the number of cores), so the answer does not depend on the thread count either. (ITK's
// pull request 6622 makes the same change upstream, with one unit per thread: its answers still
// change with the thread count.)
//
// Range. ITK takes the moving histogram's range from the whole moving image's minimum and
// maximum and the fixed one's from the samples: one padding voxel of -2048 in a converted copy
// changed the bins and the answer (by 0.010 deg). Here both are [low, high], the range the
// images are clamped to.
#include <itkMattesMutualInformationImageToImageMetricv4.h>
#include <itkMattesMutualInformationImageToImageMetricv4GetValueAndDerivativeThreader.h>

#include <memory>
#include <mutex>
#include <vector>

namespace maxillo::itk_registration {

template <typename TFixedImage, typename TMovingImage>
class OrderedMattesMetric : public itk::MattesMutualInformationImageToImageMetricv4<TFixedImage, TMovingImage> {
 public:
  using Self = OrderedMattesMetric;
  using Superclass = itk::MattesMutualInformationImageToImageMetricv4<TFixedImage, TMovingImage>;
  using Pointer = itk::SmartPointer<Self>;
  using JointPDFDerivativesType = typename Superclass::JointPDFDerivativesType;
  itkNewMacro(Self) itkTypeMacro(OrderedMattesMetric, MattesMutualInformationImageToImageMetricv4)

      // Samples are split into this many contiguous ranges whatever the number of threads.
      static constexpr itk::ThreadIdType kWorkUnits = 16;

  void SetIntensityRange(double low, double high) {
    low_ = low;
    high_ = high;
    this->Modified();
  }

  void Initialize() override {
    Superclass::Initialize();
    // The bins as ITK lays them out (two padding bins each side for the cubic Parzen window),
    // over [low, high] instead of the observed extremes.
    constexpr double padding = 2;
    const double inner_bins = double(this->m_NumberOfHistogramBins) - 2 * padding;
    this->m_FixedImageTrueMin = this->m_MovingImageTrueMin = low_;
    this->m_FixedImageTrueMax = this->m_MovingImageTrueMax = high_;
    this->m_FixedImageBinSize = this->m_MovingImageBinSize = (high_ - low_) / inner_bins;
    this->m_FixedImageNormalizedMin = this->m_MovingImageNormalizedMin = low_ / this->m_FixedImageBinSize - padding;
  }

  // Called by the threader after ITK's set-up: every unit's derivative buffer now empties into
  // the unit's own zeroed array.
  void SeparateDerivativeSums(itk::ThreadIdType units) {
    const auto region = this->m_JointPDFDerivatives->GetBufferedRegion();
    if (unit_sums_.size() != units || unit_sums_.front()->GetBufferedRegion() != region) {
      unit_sums_.assign(units, nullptr);
      for (auto& sum : unit_sums_) {
        sum = JointPDFDerivativesType::New();
        sum->SetRegions(region);
        sum->Allocate();
      }
      unit_locks_ = std::make_unique<std::mutex[]>(units);
    }
    const size_t parameters = this->m_ThreaderDerivativeManager.front().GetCachedNumberOfLocalParameters();
    const size_t bins = this->m_NumberOfHistogramBins;
    for (itk::ThreadIdType unit = 0; unit < units; ++unit) {
      unit_sums_[unit]->FillBuffer(0);
      // The buffer length ITK's threader chose (BeforeThreadedExecution).
      this->m_ThreaderDerivativeManager[unit].Initialize(std::max<size_t>(500, bins * bins / units), parameters,
                                                         &unit_locks_[unit], unit_sums_[unit]);
    }
  }

  // Called by the threader after the threads finish: the units' arrays added in unit order.
  void AddDerivativeSumsInOrder() {
    auto* total = this->m_JointPDFDerivatives->GetBufferPointer();
    const size_t count = this->m_JointPDFDerivatives->GetBufferedRegion().GetNumberOfPixels();
    for (const auto& sum : unit_sums_) {
      const auto* unit = sum->GetBufferPointer();
      for (size_t n = 0; n < count; ++n) total[n] += unit[n];
    }
  }

  bool SumsDerivativesPerUnit() const { return this->GetComputeDerivative() && !this->HasLocalSupport(); }

 protected:
  OrderedMattesMetric();

 private:
  double low_ = -1000, high_ = 2000;
  std::vector<typename JointPDFDerivativesType::Pointer> unit_sums_;
  std::unique_ptr<std::mutex[]> unit_locks_;
};

// ITK's Mattes threader over the sample list (or, unused here, the image region), with the
// fixed number of work units and the per-unit derivative sums of OrderedMattesMetric.
template <typename TPartitioner, typename TMetric>
class OrderedMattesThreader
    : public itk::MattesMutualInformationImageToImageMetricv4GetValueAndDerivativeThreader<
          TPartitioner, typename TMetric::Superclass::Superclass, typename TMetric::Superclass> {
 public:
  using Self = OrderedMattesThreader;
  using Superclass = itk::MattesMutualInformationImageToImageMetricv4GetValueAndDerivativeThreader<
      TPartitioner, typename TMetric::Superclass::Superclass, typename TMetric::Superclass>;
  using Pointer = itk::SmartPointer<Self>;
  itkNewMacro(Self)
      itkTypeMacro(OrderedMattesThreader, MattesMutualInformationImageToImageMetricv4GetValueAndDerivativeThreader)

          protected : OrderedMattesThreader() {
    this->SetNumberOfWorkUnits(TMetric::kWorkUnits);
  }

  void BeforeThreadedExecution() override {
    Superclass::BeforeThreadedExecution();
    if (metric()->SumsDerivativesPerUnit()) metric()->SeparateDerivativeSums(this->GetNumberOfWorkUnitsUsed());
  }

  void AfterThreadedExecution() override {
    if (metric()->SumsDerivativesPerUnit()) metric()->AddDerivativeSumsInOrder();
    Superclass::AfterThreadedExecution();
  }

 private:
  TMetric* metric() const { return static_cast<TMetric*>(this->m_Associate); }
};

template <typename TFixedImage, typename TMovingImage>
OrderedMattesMetric<TFixedImage, TMovingImage>::OrderedMattesMetric() {
  this->m_DenseGetValueAndDerivativeThreader =
      OrderedMattesThreader<itk::ThreadedImageRegionPartitioner<3>, Self>::New();
  this->m_SparseGetValueAndDerivativeThreader =
      OrderedMattesThreader<itk::ThreadedIndexedContainerPartitioner, Self>::New();
}

}  // namespace maxillo::itk_registration
