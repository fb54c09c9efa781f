// MetaImage/NRRD reading with ITK (see itk_filters.h). The ImageIO is chosen from the extension
// and set explicitly, so no ITK IO factory registration is needed. ITK only: no Eigen.
#include <itkImage.h>
#include <itkImageFileReader.h>
#include <itkMetaImageIO.h>
#include <itkNrrdImageIO.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/error.h"
#include "imaging/itk_filters.h"

namespace maxillo::itk_filters {
namespace {

using FloatImage = itk::Image<float, 3>;

itk::ImageIOBase::Pointer image_io_for(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (extension == ".mhd" || extension == ".mha") return itk::MetaImageIO::New().GetPointer();
  if (extension == ".nrrd" || extension == ".nhdr") return itk::NrrdImageIO::New().GetPointer();
  throw Error(ErrorCode::kUnsupportedSyntax, path,
              "unknown volume extension '" + extension + "' (known: .mhd, .mha, .nrrd, .nhdr)");
}

void check_scalar_3d(itk::ImageIOBase* io, const std::string& path) {
  io->SetFileName(path);
  try {
    io->ReadImageInformation();
  } catch (const itk::ExceptionObject& e) {
    throw Error(ErrorCode::kBadValue, path, std::string("cannot read the header: ") + e.GetDescription());
  }
  if (io->GetNumberOfDimensions() != 3)
    throw Error(ErrorCode::kUnsupportedSyntax, path,
                std::to_string(io->GetNumberOfDimensions()) + "-dimensional image, expected 3");
  if (io->GetNumberOfComponents() != 1)
    throw Error(ErrorCode::kUnsupportedSyntax, path,
                std::to_string(io->GetNumberOfComponents()) + " components per voxel, expected 1 (scalar)");
}

}  // namespace

RawVolume read_scalar_volume(const std::string& path) {
  itk::ImageIOBase::Pointer io = image_io_for(path);
  check_scalar_3d(io, path);
  auto reader = itk::ImageFileReader<FloatImage>::New();
  reader->SetImageIO(io);
  reader->SetFileName(path);
  try {
    reader->Update();
  } catch (const itk::ExceptionObject& e) {
    throw Error(ErrorCode::kBadValue, path, std::string("cannot read the voxels: ") + e.GetDescription());
  }
  const FloatImage* image = reader->GetOutput();
  RawVolume raw;
  const auto size = image->GetLargestPossibleRegion().GetSize();
  for (int a = 0; a < 3; ++a) {
    raw.grid.size[a] = size[a];
    raw.grid.spacing[a] = image->GetSpacing()[a];
    raw.origin[a] = image->GetOrigin()[a];
    for (int b = 0; b < 3; ++b) raw.direction[3 * a + b] = image->GetDirection()(a, b);
  }
  const size_t count = image->GetLargestPossibleRegion().GetNumberOfPixels();
  raw.values.assign(image->GetBufferPointer(), image->GetBufferPointer() + count);
  return raw;
}

}  // namespace maxillo::itk_filters
