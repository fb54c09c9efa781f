#pragma once
// How many bytes of pixels a DICOM data set really holds, native or encapsulated, shared by
// the import's check (an image without its pixels is refused) and the slice reader (a frame is
// allocated only for what is stored). Private to the dicom module: it speaks DCMTK's types.
#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdatset.h>
#include <dcmtk/dcmdata/dcpixel.h>

#include <cstddef>
#include <optional>
#include <string>

namespace maxillo {

// Whether the data set's pixels are stored compressed (an encapsulated transfer syntax).
bool pixels_are_encapsulated(DcmDataset& dataset);

// The bytes of Pixel Data as stored: the value's length for native pixels; for encapsulated
// pixels the sum of the fragments' lengths (the Basic Offset Table item left out). DCMTK's
// getLength() answers for the native representation, which encapsulated data does not have
// yet, so it said 0 for every compressed file (issue 29, fault 3).
size_t stored_pixel_bytes(DcmDataset& dataset, DcmPixelData& pixel_data);

// For RLE Lossless pixels (PS3.5 annex G), what is wrong with a fragment's header, if anything:
// a fragment shorter than the 64-byte header, a segment count outside 1-15, a first segment not
// at byte 64, or a segment offset that does not rise or lies beyond the fragment. DCMTK's decoder
// trusts the offsets and reads past the fragment (a fuzzing finding: SEGV in
// DcmRLEDecoder::decompress). nullopt for valid headers and for every other transfer syntax.
std::optional<std::string> rle_header_fault(DcmDataset& dataset, DcmPixelData& pixel_data);

// For the JPEG transfer syntaxes DCMTK's IJG decoder reads (PS3.5 processes 1-29 and 14 SV1), what
// is wrong with a fragment's markers before its first start of frame, if anything: a TEM marker
// (FF01) there. DCMTK's scan for the bit depth does not step over a TEM and spins on it for ever
// (a fuzzing finding: a hang in DJCodecDecoder::scanJpegDataForBitDepth). nullopt otherwise, and
// for every other transfer syntax; a stream that is not JPEG at all is the decoder's to refuse.
std::optional<std::string> jpeg_header_fault(DcmDataset& dataset, DcmPixelData& pixel_data);

// The Pixel Data element of the data set, or null when there is none (or it is not encoded as
// pixel data).
DcmPixelData* pixel_data_of(DcmDataset& dataset);

}  // namespace maxillo
