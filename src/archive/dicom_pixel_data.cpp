#include "archive/dicom_pixel_data.h"

#include <cstdint>

#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcpixseq.h>
#include <dcmtk/dcmdata/dcpxitem.h>
#include <dcmtk/dcmdata/dcxfer.h>

namespace maxillo {

bool pixels_are_encapsulated(DcmDataset& dataset) { return DcmXfer(dataset.getOriginalXfer()).isEncapsulated(); }

size_t stored_pixel_bytes(DcmDataset& dataset, DcmPixelData& pixel_data) {
  if (!pixels_are_encapsulated(dataset)) return pixel_data.getLength();
  DcmPixelSequence* fragments = nullptr;
  if (pixel_data.getEncapsulatedRepresentation(dataset.getOriginalXfer(), nullptr, fragments).bad() ||
      fragments == nullptr)
    return 0;
  size_t total = 0;
  for (unsigned long n = 1; n < fragments->card(); ++n) {  // item 0 is the Basic Offset Table
    DcmPixelItem* fragment = nullptr;
    if (fragments->getItem(fragment, n).good() && fragment != nullptr) total += fragment->getLength();
  }
  return total;
}

namespace {

constexpr size_t kRleHeaderBytes = 64;
constexpr uint32_t kRleMaxSegments = 15;

uint32_t little_endian_u32(const Uint8* bytes) {
  return uint32_t(bytes[0]) | uint32_t(bytes[1]) << 8 | uint32_t(bytes[2]) << 16 | uint32_t(bytes[3]) << 24;
}

// What is wrong with one RLE fragment's header, if anything.
std::optional<std::string> rle_fragment_fault(const Uint8* bytes, size_t length) {
  if (length <= kRleHeaderBytes) return "is " + std::to_string(length) + " bytes, no more than the RLE header (64)";
  const uint32_t segments = little_endian_u32(bytes);
  if (segments < 1 || segments > kRleMaxSegments)
    return "declares " + std::to_string(segments) + " RLE segments (1 to 15 allowed)";
  if (little_endian_u32(bytes + 4) != kRleHeaderBytes) return "has its first RLE segment elsewhere than at byte 64";
  for (uint32_t s = 1; s < segments; ++s) {
    const uint32_t offset = little_endian_u32(bytes + 4 + 4 * s), previous = little_endian_u32(bytes + 4 * s);
    if (offset <= previous || offset >= length)
      return "has RLE segment " + std::to_string(s + 1) + " at byte " + std::to_string(offset) +
             ", not after the previous one within its " + std::to_string(length) + " bytes";
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> rle_header_fault(DcmDataset& dataset, DcmPixelData& pixel_data) {
  if (dataset.getOriginalXfer() != EXS_RLELossless) return std::nullopt;
  DcmPixelSequence* fragments = nullptr;
  if (pixel_data.getEncapsulatedRepresentation(dataset.getOriginalXfer(), nullptr, fragments).bad() ||
      fragments == nullptr)
    return std::nullopt;                                   // no fragments: the decoder says so itself
  for (unsigned long n = 1; n < fragments->card(); ++n) {  // item 0 is the Basic Offset Table
    DcmPixelItem* fragment = nullptr;
    Uint8* bytes = nullptr;
    if (fragments->getItem(fragment, n).bad() || fragment == nullptr || fragment->getUint8Array(bytes).bad())
      return "fragment " + std::to_string(n) + " cannot be read";
    if (auto fault = rle_fragment_fault(bytes, bytes ? fragment->getLength() : 0))
      return "fragment " + std::to_string(n) + " " + *fault;
  }
  return std::nullopt;
}

DcmPixelData* pixel_data_of(DcmDataset& dataset) {
  DcmElement* element = nullptr;
  if (dataset.findAndGetElement(DCM_PixelData, element).bad() || element == nullptr) return nullptr;
  // A damaged VR makes DCMTK read (7FE0,0010) as some other kind of element.
  return dynamic_cast<DcmPixelData*>(element);
}

}  // namespace maxillo
