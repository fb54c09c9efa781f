// ITK morphology on plain 0/1 buffers (see itk_filters.h). ITK only: no Eigen, no maxillo types.
#include "imaging/itk_filters.h"

#include <itkBinaryBallStructuringElement.h>
#include <itkBinaryDilateImageFilter.h>
#include <itkBinaryFillholeImageFilter.h>
#include <itkBinaryMorphologicalOpeningImageFilter.h>
#include <itkConnectedComponentImageFilter.h>
#include <itkImage.h>
#include <itkRelabelComponentImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace maxillo::itk_filters {
namespace {

using MaskImage = itk::Image<uint8_t, 3>;
using ComponentImage = itk::Image<uint32_t, 3>;
using Ball = itk::BinaryBallStructuringElement<uint8_t, 3>;

MaskImage::Pointer to_itk(const Mask& mask, const Grid& grid) {
  auto image = MaskImage::New();
  MaskImage::SizeType size{{grid.size[0], grid.size[1], grid.size[2]}};
  image->SetRegions(MaskImage::RegionType(size));
  MaskImage::SpacingType spacing;
  for (int a = 0; a < 3; ++a) spacing[a] = grid.spacing[a];
  image->SetSpacing(spacing);
  image->Allocate();
  std::memcpy(image->GetBufferPointer(), mask.data(), mask.size());
  return image;
}

Mask from_itk(const MaskImage* image) {
  const size_t count = image->GetLargestPossibleRegion().GetNumberOfPixels();
  return Mask(image->GetBufferPointer(), image->GetBufferPointer() + count);
}

Ball ball_of_radius(double radius_mm, const Grid& grid) {
  Ball ball;
  Ball::SizeType radius;
  for (int a = 0; a < 3; ++a) radius[a] = std::max<long>(1, std::lround(radius_mm / grid.spacing[a]));
  ball.SetRadius(radius);
  ball.CreateStructuringElement();
  return ball;
}

// Components relabelled by decreasing size (1 = largest), those under min_voxels dropped (0).
ComponentImage::Pointer ranked_components(const Mask& mask, const Grid& grid, int64_t min_voxels) {
  auto components = itk::ConnectedComponentImageFilter<MaskImage, ComponentImage>::New();
  components->SetInput(to_itk(mask, grid));
  components->FullyConnectedOff();
  auto relabel = itk::RelabelComponentImageFilter<ComponentImage, ComponentImage>::New();
  relabel->SetInput(components->GetOutput());
  relabel->SetMinimumObjectSize(std::max<int64_t>(min_voxels, 1));
  relabel->Update();
  return relabel->GetOutput();
}

}  // namespace

Mask largest_component(const Mask& mask, const Grid& grid) {
  auto ranked = ranked_components(mask, grid, 1);
  const uint32_t* labels = ranked->GetBufferPointer();
  Mask out(mask.size());
  for (size_t n = 0; n < mask.size(); ++n) out[n] = labels[n] == 1;
  return out;
}

Mask components_of_at_least(const Mask& mask, const Grid& grid, int64_t min_voxels) {
  auto ranked = ranked_components(mask, grid, min_voxels);
  const uint32_t* labels = ranked->GetBufferPointer();
  Mask out(mask.size());
  for (size_t n = 0; n < mask.size(); ++n) out[n] = labels[n] > 0;
  return out;
}

Mask opened(const Mask& mask, const Grid& grid, double radius_mm) {
  auto opening = itk::BinaryMorphologicalOpeningImageFilter<MaskImage, MaskImage, Ball>::New();
  opening->SetInput(to_itk(mask, grid));
  opening->SetKernel(ball_of_radius(radius_mm, grid));
  opening->SetForegroundValue(1);
  opening->SetBackgroundValue(0);
  opening->Update();
  return from_itk(opening->GetOutput());
}

Mask dilated(const Mask& mask, const Grid& grid, double radius_mm) {
  auto dilation = itk::BinaryDilateImageFilter<MaskImage, MaskImage, Ball>::New();
  dilation->SetInput(to_itk(mask, grid));
  dilation->SetKernel(ball_of_radius(radius_mm, grid));
  dilation->SetForegroundValue(1);
  dilation->SetBackgroundValue(0);
  dilation->Update();
  return from_itk(dilation->GetOutput());
}

Mask holes_filled(const Mask& mask, const Grid& grid) {
  auto fill = itk::BinaryFillholeImageFilter<MaskImage>::New();
  fill->SetInput(to_itk(mask, grid));
  fill->SetForegroundValue(1);
  fill->FullyConnectedOff();
  fill->Update();
  return from_itk(fill->GetOutput());
}

}  // namespace maxillo::itk_filters
