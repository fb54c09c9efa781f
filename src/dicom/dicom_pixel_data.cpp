#include "dicom/dicom_pixel_data.h"

#include <cstdint>
#include <variant>
#include <vector>

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

// The markers DCMTK's bit-depth scan steps over by their segment's length: DHT, DAC, SOS, DQT,
// DNL, DRI, DHP, EXP, the APPn, the JPGn, COM and the reserved FFC8.
bool has_segment_length(uint16_t marker) {
  return marker == 0xffc4 || marker == 0xffc8 || marker == 0xffcc || (marker >= 0xffda && marker <= 0xffdf) ||
         (marker >= 0xffe0 && marker <= 0xfffe);
}

bool is_start_of_frame(uint16_t marker) {
  return marker >= 0xffc0 && marker <= 0xffcf && marker != 0xffc4 && marker != 0xffc8 && marker != 0xffcc;
}

uint16_t big_endian_u16(const Uint8* bytes) { return uint16_t(bytes[0] << 8 | bytes[1]); }

// Walks a JPEG fragment's markers as DCMTK's scan does, up to the first start of frame.
std::optional<std::string> jpeg_fragment_fault(const Uint8* bytes, size_t length) {
  for (size_t offset = 0; offset + 4 < length;) {
    const uint16_t marker = big_endian_u16(bytes + offset);
    if (is_start_of_frame(marker)) return std::nullopt;
    if (marker == 0xff01)
      return "has a TEM marker (FF01) at byte " + std::to_string(offset) + " before its start of frame";
    if (has_segment_length(marker))
      offset += big_endian_u16(bytes + offset + 2) + 2;
    else if (marker == 0xffff)  // a fill byte
      offset += 1;
    else if (bytes[offset] == 0xff && bytes[offset + 1] > 2 && bytes[offset + 1] <= 0xdf)  // RSTn, SOI, EOI, reserved
      offset += 2;
    else
      return std::nullopt;  // not a marker: DCMTK stops there and refuses the stream itself
  }
  return std::nullopt;
}

bool read_by_dcmtk_ijg_decoder(E_TransferSyntax syntax) {
  return (syntax >= EXS_JPEGProcess1 && syntax <= EXS_JPEGProcess29) || syntax == EXS_JPEGProcess14SV1;
}

struct Fragment {
  const Uint8* bytes = nullptr;
  size_t length = 0;
};

// The pixel data's fragments (item 0, the Basic Offset Table, left out), or why one cannot be read.
// An empty list when the data set has no fragments: the decoder says so itself.
std::variant<std::vector<Fragment>, std::string> fragments_of(DcmDataset& dataset, DcmPixelData& pixel_data) {
  std::vector<Fragment> fragments;
  DcmPixelSequence* sequence = nullptr;
  if (pixel_data.getEncapsulatedRepresentation(dataset.getOriginalXfer(), nullptr, sequence).bad() ||
      sequence == nullptr)
    return fragments;
  for (unsigned long n = 1; n < sequence->card(); ++n) {
    DcmPixelItem* item = nullptr;
    Uint8* bytes = nullptr;
    if (sequence->getItem(item, n).bad() || item == nullptr || item->getUint8Array(bytes).bad())
      return "fragment " + std::to_string(n) + " cannot be read";
    fragments.push_back({bytes, bytes ? size_t(item->getLength()) : 0});
  }
  return fragments;
}

}  // namespace

std::optional<std::string> jpeg_header_fault(DcmDataset& dataset, DcmPixelData& pixel_data) {
  if (!read_by_dcmtk_ijg_decoder(dataset.getOriginalXfer())) return std::nullopt;
  auto fragments = fragments_of(dataset, pixel_data);
  if (auto* unreadable = std::get_if<std::string>(&fragments)) return *unreadable;
  // DCMTK scans the first fragment of the frame it decodes, frame 0: the first fragment.
  const auto& list = std::get<std::vector<Fragment>>(fragments);
  if (list.empty()) return std::nullopt;
  if (auto fault = jpeg_fragment_fault(list.front().bytes, list.front().length)) return "fragment 1 " + *fault;
  return std::nullopt;
}

std::optional<std::string> rle_header_fault(DcmDataset& dataset, DcmPixelData& pixel_data) {
  if (dataset.getOriginalXfer() != EXS_RLELossless) return std::nullopt;
  auto fragments = fragments_of(dataset, pixel_data);
  if (auto* unreadable = std::get_if<std::string>(&fragments)) return *unreadable;
  const auto& list = std::get<std::vector<Fragment>>(fragments);
  for (size_t n = 0; n < list.size(); ++n)
    if (auto fault = rle_fragment_fault(list[n].bytes, list[n].length))
      return "fragment " + std::to_string(n + 1) + " " + *fault;
  return std::nullopt;
}

DcmPixelData* pixel_data_of(DcmDataset& dataset) {
  DcmElement* element = nullptr;
  if (dataset.findAndGetElement(DCM_PixelData, element).bad() || element == nullptr) return nullptr;
  // A damaged VR makes DCMTK read (7FE0,0010) as some other kind of element.
  return dynamic_cast<DcmPixelData*>(element);
}

}  // namespace maxillo
