// DICOM image file -> DicomSlice (geometry + HU pixels) with DCMTK.
// Pixels are fetched with DcmPixelData::getUncompressedFrame, which goes through the registered
// decoders (JPEG, JPEG-LS, RLE) for encapsulated syntaxes and copies native data otherwise; the
// result is in host byte order with BitsAllocated bits per sample. Stored bits are then masked,
// sign-extended when PixelRepresentation = 1, inverted for MONOCHROME1, and rescaled to HU.
#include "dicom/dicom_slice_reader.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dccodec.h>
#include <dcmtk/dcmdata/dcdatset.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcistrmb.h>
#include <dcmtk/dcmdata/dcpixel.h>
#include <dcmtk/dcmdata/dcxfer.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "core/atomic_file.h"
#include "core/error.h"
#include "dicom/dicom_header.h"
#include "dicom/dicom_pixel_data.h"
#include "dicom/dicom_structure.h"

namespace maxillo {
namespace {

struct Reading {
  const std::filesystem::path& path;
  DcmDataset& dataset;

  [[noreturn]] void fail(ErrorCode code, const std::string& reason) const { throw Error(code, path.string(), reason); }
  std::string string_or_empty(const DcmTagKey& tag) const {
    OFString value;
    if (dataset.findAndGetOFString(tag, value).bad()) return {};
    return value.c_str();
  }
  double required_double(const DcmTagKey& tag, unsigned long index, const char* name) const {
    Float64 value = 0;
    if (dataset.findAndGetFloat64(tag, value, index).bad())
      fail(ErrorCode::kMissingAttribute, std::string(name) + " is missing or has too few values");
    if (!std::isfinite(value)) fail(ErrorCode::kBadValue, std::string(name) + " is not a finite number");
    return value;
  }
  std::optional<double> optional_double(const DcmTagKey& tag) const {
    Float64 value = 0;
    if (dataset.findAndGetFloat64(tag, value).bad() || !std::isfinite(value)) return std::nullopt;
    return value;
  }
  int required_uint16(const DcmTagKey& tag, const char* name) const {
    Uint16 value = 0;
    if (dataset.findAndGetUint16(tag, value).bad())
      fail(ErrorCode::kMissingAttribute, std::string(name) + " is missing");
    return value;
  }
};

void read_geometry(const Reading& r, DicomSlice& slice) {
  for (int a = 0; a < 3; ++a)
    slice.position[a] = r.required_double(DCM_ImagePositionPatient, a, "Image Position (Patient)");
  for (int a = 0; a < 3; ++a) {
    slice.row_direction[a] = r.required_double(DCM_ImageOrientationPatient, a, "Image Orientation (Patient)");
    slice.column_direction[a] = r.required_double(DCM_ImageOrientationPatient, a + 3, "Image Orientation (Patient)");
  }
  // DS values carry ~6-10 digits: renormalise, but refuse vectors that are not unit or orthogonal.
  double row_norm = slice.row_direction.norm(), column_norm = slice.column_direction.norm();
  if (std::abs(row_norm - 1) > 1e-3 || std::abs(column_norm - 1) > 1e-3 ||
      std::abs(slice.row_direction.dot(slice.column_direction)) > 1e-3)
    r.fail(ErrorCode::kBadValue, "Image Orientation (Patient) is not two orthogonal unit vectors");
  slice.row_direction /= row_norm;
  slice.column_direction /= column_norm;
  slice.row_spacing = r.required_double(DCM_PixelSpacing, 0, "Pixel Spacing");
  slice.column_spacing = r.required_double(DCM_PixelSpacing, 1, "Pixel Spacing");
  if (slice.row_spacing <= 0 || slice.column_spacing <= 0)
    r.fail(ErrorCode::kBadValue, "Pixel Spacing is not positive");
  slice.gantry_tilt_degrees = r.optional_double(DCM_GantryDetectorTilt);
}

void check_image_kind(const Reading& r, const std::string& photometric) {
  if (photometric != "MONOCHROME1" && photometric != "MONOCHROME2")
    r.fail(ErrorCode::kUnsupportedSyntax,
           "photometric interpretation '" + photometric + "' is not a greyscale image (MONOCHROME1/2 expected)");
  Sint32 frames = 1;
  if (r.dataset.findAndGetSint32(DCM_NumberOfFrames, frames).good() && frames > 1)
    r.fail(ErrorCode::kUnsupportedSyntax, "multi-frame image (" + std::to_string(frames) + " frames)");
  Uint16 samples = 1;
  if (r.dataset.findAndGetUint16(DCM_SamplesPerPixel, samples).good() && samples != 1)
    r.fail(ErrorCode::kUnsupportedSyntax, "samples per pixel is " + std::to_string(samples) + ", expected 1");
}

void check_transfer_syntax(const Reading& r) {
  E_TransferSyntax syntax = r.dataset.getOriginalXfer();
  DcmXfer xfer(syntax);
  if (xfer.isEncapsulated() && !DcmCodecList::canChangeCoding(syntax, EXS_LittleEndianExplicit))
    r.fail(ErrorCode::kUnsupportedSyntax,
           std::string("no decoder for transfer syntax ") + xfer.getXferName() + " (" + xfer.getXferID() + ")");
}

// The stored value of sample `index` as an integer: masked to BitsStored, sign-extended if signed.
struct SampleLayout {
  int bits_allocated, bits_stored;
  bool is_signed;
  int32_t value(const std::vector<uint8_t>& frame, size_t index) const {
    uint32_t raw;
    if (bits_allocated == 8) {
      raw = frame[index];
    } else {
      uint16_t word;
      std::memcpy(&word, frame.data() + 2 * index, 2);
      raw = word;
    }
    uint32_t mask = (bits_stored >= 32) ? 0xffffffffu : ((1u << bits_stored) - 1u);
    raw &= mask;
    if (is_signed && (raw & (1u << (bits_stored - 1)))) return int32_t(raw) - int32_t(1u << bits_stored);
    return int32_t(raw);
  }
};

// The decoded frame is allocated from Rows x Columns, which a header can set to 65535 x 65535
// (8 GiB): check the claim against the bytes really stored before allocating. Native pixel data
// must hold the whole frame; compressed data is allowed a generous 1:1000 ratio.
void check_frame_size(const Reading& r, DcmPixelData& pixel_data, size_t frame_bytes) {
  constexpr size_t kMaxCompressionRatio = 1000;
  const size_t stored = stored_pixel_bytes(r.dataset, pixel_data);
  const bool encapsulated = pixels_are_encapsulated(r.dataset);
  if (!encapsulated && stored < frame_bytes)
    r.fail(ErrorCode::kBadValue, "Pixel Data holds " + std::to_string(stored) + " bytes, Rows x Columns needs " +
                                     std::to_string(frame_bytes));
  if (encapsulated && frame_bytes / kMaxCompressionRatio > stored)
    r.fail(ErrorCode::kBadValue, "Rows x Columns (" + std::to_string(frame_bytes) + " bytes) is implausible for " +
                                     std::to_string(stored) + " bytes of compressed pixel data");
}

void read_pixels(const Reading& r, DicomSlice& slice, const std::string& photometric) {
  SampleLayout layout{r.required_uint16(DCM_BitsAllocated, "Bits Allocated"), 0, false};
  if (layout.bits_allocated != 8 && layout.bits_allocated != 16)
    r.fail(ErrorCode::kUnsupportedSyntax,
           "bits allocated is " + std::to_string(layout.bits_allocated) + ", expected 8 or 16");
  Uint16 stored = 0, representation = 0;
  layout.bits_stored = r.dataset.findAndGetUint16(DCM_BitsStored, stored).good() ? stored : layout.bits_allocated;
  if (layout.bits_stored < 1 || layout.bits_stored > layout.bits_allocated)
    r.fail(ErrorCode::kBadValue, "bits stored " + std::to_string(layout.bits_stored) + " does not fit bits allocated");
  r.dataset.findAndGetUint16(DCM_PixelRepresentation, representation);
  layout.is_signed = representation == 1;

  if (!r.dataset.tagExists(DCM_PixelData)) r.fail(ErrorCode::kMissingAttribute, "Pixel Data is missing");
  auto* pixel_data = pixel_data_of(r.dataset);
  if (pixel_data == nullptr) r.fail(ErrorCode::kNotDicom, "Pixel Data (7FE0,0010) is not encoded as pixel data");
  const size_t count = size_t(slice.rows) * slice.columns;
  check_frame_size(r, *pixel_data, count * (layout.bits_allocated / 8));
  if (auto fault = rle_header_fault(r.dataset, *pixel_data)) r.fail(ErrorCode::kBadValue, "Pixel Data: " + *fault);
  if (auto fault = jpeg_header_fault(r.dataset, *pixel_data)) r.fail(ErrorCode::kBadValue, "Pixel Data: " + *fault);
  std::vector<uint8_t> frame(count * (layout.bits_allocated / 8) + 1);  // even size for DCMTK
  Uint32 start_fragment = 0;
  OFString colour_model;
  OFCondition status = pixel_data->getUncompressedFrame(&r.dataset, 0, start_fragment, frame.data(),
                                                        Uint32(frame.size() & ~size_t(1)), colour_model);
  if (status.bad()) r.fail(ErrorCode::kBadValue, std::string("cannot decode pixel data: ") + status.text());

  const bool invert = photometric == "MONOCHROME1";
  const int32_t max_stored = layout.is_signed ? (1 << (layout.bits_stored - 1)) - 1 : (1 << layout.bits_stored) - 1;
  const int32_t min_stored = layout.is_signed ? -(1 << (layout.bits_stored - 1)) : 0;
  slice.hu.resize(count);
  for (size_t n = 0; n < count; ++n) {
    int32_t stored_value = layout.value(frame, n);
    if (invert) stored_value = max_stored + min_stored - stored_value;
    double hu = std::round(slice.rescale_slope * stored_value + slice.rescale_intercept);
    slice.hu[n] = int16_t(std::clamp(hu, -32768.0, 32767.0));
  }
}

}  // namespace

DicomSlice read_dicom_slice(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw Error(ErrorCode::kFileNotFound, path.string(), "no such file");
  return decode_dicom_slice(read_file(path), path);
}

DicomSlice decode_dicom_slice(std::span<const std::byte> bytes, const std::filesystem::path& path) {
  initialise_dicom_toolkit();          // decoders, and DCMTK told how we read the file meta group
  check_dicom_structure(bytes, path);  // lengths and nesting checked before DCMTK reads them
  DcmInputBufferStream stream;
  stream.setBuffer(bytes.data(), static_cast<offile_off_t>(bytes.size()));
  stream.setEos();
  DcmFileFormat file;
  file.transferInit();
  // Every value read now (no deferred loading): the buffer is gone when this function returns.
  OFCondition status = file.read(stream, EXS_Unknown, EGL_noChange, std::numeric_limits<Uint32>::max());
  file.transferEnd();
  if (status.bad()) throw Error(ErrorCode::kNotDicom, path.string(), status.text());
  Reading r{path, *file.getDataset()};

  DicomSlice slice;
  slice.path = path;
  slice.series_instance_uid = r.string_or_empty(DCM_SeriesInstanceUID);
  slice.sop_instance_uid = r.string_or_empty(DCM_SOPInstanceUID);
  if (slice.series_instance_uid.empty()) r.fail(ErrorCode::kMissingAttribute, "Series Instance UID is missing");
  Sint32 instance = 0;
  if (r.dataset.findAndGetSint32(DCM_InstanceNumber, instance).good()) slice.instance_number = instance;

  std::string photometric = r.string_or_empty(DCM_PhotometricInterpretation);
  check_image_kind(r, photometric);
  check_transfer_syntax(r);
  read_geometry(r, slice);
  slice.rows = r.required_uint16(DCM_Rows, "Rows");
  slice.columns = r.required_uint16(DCM_Columns, "Columns");
  if (slice.rows == 0 || slice.columns == 0) r.fail(ErrorCode::kBadValue, "image has zero rows or columns");
  slice.rescale_slope = r.optional_double(DCM_RescaleSlope).value_or(1.0);
  slice.rescale_intercept = r.optional_double(DCM_RescaleIntercept).value_or(0.0);
  if (slice.rescale_slope == 0) r.fail(ErrorCode::kBadValue, "Rescale Slope is zero");
  read_pixels(r, slice, photometric);
  return slice;
}

}  // namespace maxillo
