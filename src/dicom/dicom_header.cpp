#include "dicom/dicom_header.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dccodec.h>
#include <dcmtk/dcmdata/dcdatset.h>
#include <dcmtk/dcmdata/dcobject.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcistrmb.h>
#include <dcmtk/dcmdata/dcmetinf.h>
#include <dcmtk/dcmdata/dcrledrg.h>
#include <dcmtk/dcmdata/dcxfer.h>
#include <dcmtk/dcmjpeg/djdecode.h>
#include <dcmtk/dcmjpls/djdecode.h>
#include <dcmtk/oflog/oflog.h>

#include <algorithm>
#include <cstring>
#include <mutex>

#include "core/error.h"
#include "core/utf8.h"
#include "dicom/dicom_pixel_data.h"
#include "dicom/dicom_structure.h"
#include "dicom/dicom_uid.h"

namespace maxillo {
namespace {

constexpr size_t kPreambleLength = 128;

bool has_dicm_prefix(std::span<const std::byte> bytes) {
  return bytes.size() >= kPreambleLength + 4 && std::memcmp(bytes.data() + kPreambleLength, "DICM", 4) == 0;
}

// Text as UTF-8: values in a declared character set were converted by DCMTK; bytes that are
// still not UTF-8 (accented letters with no Specific Character Set declared) are read as
// Latin-1, the usual encoding of such files (documented in ARCHITECTURE.md).
std::string text_of(DcmItem& item, const DcmTagKey& tag) {
  OFString value;
  if (item.findAndGetOFStringArray(tag, value).bad()) return {};
  return repaired_utf8(std::string_view(value.c_str(), value.length()));
}

std::optional<int> integer_of(DcmItem& item, const DcmTagKey& tag) {
  Sint32 value = 0;
  if (item.findAndGetSint32(tag, value).good()) return value;
  return std::nullopt;
}

std::optional<int> unsigned_of(DcmItem& item, const DcmTagKey& tag) {
  Uint16 value = 0;
  if (item.findAndGetUint16(tag, value).good()) return value;
  return std::nullopt;
}

std::optional<double> decimal_of(DcmItem& item, const DcmTagKey& tag, unsigned long index = 0) {
  Float64 value = 0;
  if (item.findAndGetFloat64(tag, value, index).good()) return value;
  return std::nullopt;
}

// Whether DCMTK can decode pixel data stored in this transfer syntax.
void require_supported_syntax(const std::string& uid, const std::filesystem::path& path) {
  if (uid.empty()) throw Error(ErrorCode::kMissingAttribute, path.string(), "no Transfer Syntax UID (0002,0010)");
  DcmXfer xfer(uid.c_str());
  if (xfer.getXfer() == EXS_Unknown)
    throw Error(ErrorCode::kUnsupportedSyntax, path.string(), "unknown transfer syntax " + uid);
  if (xfer.isEncapsulated() && !DcmCodecList::canChangeCoding(xfer.getXfer(), EXS_LittleEndianExplicit))
    throw Error(ErrorCode::kUnsupportedSyntax, path.string(),
                std::string(xfer.getXferName()) + " (" + uid + "): no decoder available");
}

void require(const std::string& value, const char* what, const std::filesystem::path& path) {
  if (value.empty()) throw Error(ErrorCode::kMissingAttribute, path.string(), std::string("no ") + what);
}

bool is_utf8_compatible(const std::string& character_set) {
  return character_set.empty() || character_set == "ISO_IR 192" || character_set == "ISO_IR 6";
}

void fill_patient_study_series(DcmDataset& d, InstanceHeader& h) {
  h.sop_class_uid = text_of(d, DCM_SOPClassUID);
  h.sop_instance_uid = text_of(d, DCM_SOPInstanceUID);
  h.patient_id = text_of(d, DCM_PatientID);
  h.patient_name = text_of(d, DCM_PatientName);
  h.birth_date = text_of(d, DCM_PatientBirthDate);
  h.sex = text_of(d, DCM_PatientSex);
  h.study_uid = text_of(d, DCM_StudyInstanceUID);
  h.study_date = text_of(d, DCM_StudyDate);
  h.study_time = text_of(d, DCM_StudyTime);
  h.study_description = text_of(d, DCM_StudyDescription);
  h.accession_number = text_of(d, DCM_AccessionNumber);
  h.series_uid = text_of(d, DCM_SeriesInstanceUID);
  h.modality = text_of(d, DCM_Modality);
  h.series_description = text_of(d, DCM_SeriesDescription);
  h.series_number = integer_of(d, DCM_SeriesNumber);
}

void fill_image(DcmDataset& d, InstanceHeader& h) {
  h.instance_number = integer_of(d, DCM_InstanceNumber);
  h.rows = unsigned_of(d, DCM_Rows);
  h.columns = unsigned_of(d, DCM_Columns);
  h.pixel_spacing_row = decimal_of(d, DCM_PixelSpacing, 0);
  h.pixel_spacing_column = decimal_of(d, DCM_PixelSpacing, 1);
  h.slice_thickness = decimal_of(d, DCM_SliceThickness);
  h.image_position = text_of(d, DCM_ImagePositionPatient);
  h.image_orientation = text_of(d, DCM_ImageOrientationPatient);
}

// An image (Rows and Columns given) must carry its pixels: a file cut before its Pixel Data,
// or whose Pixel Data holds less than Rows x Columns x frames need, is refused before anything
// is archived (issue 29, fault 4: such files were acknowledged and imported).
void require_pixels_of_an_image(DcmDataset& d, const InstanceHeader& h, const std::filesystem::path& path) {
  if (!h.rows || !h.columns) return;  // not an image (a report, a structured document)
  if (!d.tagExists(DCM_PixelData))
    throw Error(ErrorCode::kTruncated, path.string(),
                "an image (Rows x Columns " + std::to_string(*h.rows) + " x " + std::to_string(*h.columns) +
                    ") without Pixel Data (7FE0,0010): the file ends before its pixels");
  DcmPixelData* pixel_data = pixel_data_of(d);
  if (pixel_data == nullptr)
    throw Error(ErrorCode::kNotDicom, path.string(), "Pixel Data (7FE0,0010) is not encoded as pixel data");
  const size_t stored = stored_pixel_bytes(d, *pixel_data);
  if (pixels_are_encapsulated(d)) {
    if (stored == 0)
      throw Error(ErrorCode::kTruncated, path.string(), "Pixel Data (7FE0,0010) holds no compressed fragment");
    return;  // how much a frame compresses is the decoder's to check, when the pixels are read
  }
  const size_t bits = size_t(unsigned_of(d, DCM_BitsAllocated).value_or(16));
  const size_t samples = size_t(unsigned_of(d, DCM_SamplesPerPixel).value_or(1));
  const size_t frames = size_t(std::max(1, integer_of(d, DCM_NumberOfFrames).value_or(1)));
  const size_t needed = (size_t(*h.rows) * size_t(*h.columns) * samples * frames * bits + 7) / 8;
  if (stored < needed)
    throw Error(ErrorCode::kTruncated, path.string(),
                "Pixel Data (7FE0,0010) holds " + std::to_string(stored) + " bytes; Rows x Columns x frames (" +
                    std::to_string(*h.rows) + " x " + std::to_string(*h.columns) + " x " + std::to_string(frames) +
                    ") at " + std::to_string(bits) + " bits need " + std::to_string(needed));
}

// The UIDs the archive keys on and names files by must be UIDs (PS3.5 9.1): a slash or 301
// characters broke export, a NUL byte made a series reachable only by its archive id.
void require_uid(const std::string& value, const char* element, const std::filesystem::path& path) {
  if (auto fault = uid_fault(value, LeadingZeros::Tolerated))
    throw Error(ErrorCode::kBadValue, path.string(), std::string(element) + " is not a UID: " + *fault);
}

}  // namespace

void initialise_dicom_toolkit() {
  static std::once_flag once;
  std::call_once(once, [] {
    OFLog::configure(OFLogger::FATAL_LOG_LEVEL);
    // The end of the file meta group is where its elements end (as dicom_structure.h finds it),
    // not where (0002,0000) claims: a damaged group length sent DCMTK reading the data set as
    // meta elements and allocating gigabytes (a fuzzing finding).
    dcmIgnoreFileMetaInformationGroupLength.set(OFTrue);
    DJDecoderRegistration::registerCodecs();
    DJLSDecoderRegistration::registerCodecs();
    DcmRLEDecoderRegistration::registerCodecs();
  });
}

InstanceHeader parse_instance_header(std::span<const std::byte> bytes, const std::filesystem::path& path) {
  initialise_dicom_toolkit();
  if (!has_dicm_prefix(bytes))
    throw Error(ErrorCode::kNotDicom, path.string(), "no DICM prefix at byte 128 (not a DICOM Part 10 file)");
  check_dicom_structure(bytes, path);  // before DCMTK: it trusts lengths and nests on the stack

  // The whole file is already in memory (it was read once for hashing): parse from there.
  DcmInputBufferStream stream;
  stream.setBuffer(bytes.data(), static_cast<offile_off_t>(bytes.size()));
  stream.setEos();
  DcmFileFormat file;
  file.transferInit();
  OFCondition status = file.read(stream, EXS_Unknown, EGL_noChange, DCM_MaxReadLength);
  file.transferEnd();

  InstanceHeader header;
  header.transfer_syntax_uid = text_of(*file.getMetaInfo(), DCM_TransferSyntaxUID);
  if (header.transfer_syntax_uid.empty() && status.bad())
    throw Error(ErrorCode::kNotDicom, path.string(), std::string("unreadable file meta information: ") + status.text());
  require_supported_syntax(header.transfer_syntax_uid, path);
  if (status == EC_StreamNotifyClient || status == EC_ItemEnd || status == EC_SequEnd ||
      status == EC_PrematureSequDelimitationItem || status == EC_InvalidStream || (status.good() && !stream.eos()))
    throw Error(ErrorCode::kTruncated, path.string(),
                std::string("file ends inside an attribute (") + status.text() + ")");
  if (status.bad()) throw Error(ErrorCode::kNotDicom, path.string(), std::string("cannot parse: ") + status.text());

  DcmDataset& dataset = *file.getDataset();
  std::string character_set = text_of(dataset, DCM_SpecificCharacterSet);
  if (!is_utf8_compatible(character_set) && dataset.convertToUTF8().bad())
    throw Error(ErrorCode::kBadValue, path.string(), "cannot decode character set " + character_set);
  fill_patient_study_series(dataset, header);
  fill_image(dataset, header);
  require(header.sop_instance_uid, "SOP Instance UID (0008,0018)", path);
  require(header.sop_class_uid, "SOP Class UID (0008,0016)", path);
  require(header.study_uid, "Study Instance UID (0020,000D)", path);
  require(header.series_uid, "Series Instance UID (0020,000E)", path);
  require(header.patient_id, "Patient ID (0010,0020)", path);
  require_uid(header.sop_instance_uid, "SOP Instance UID (0008,0018)", path);
  require_uid(header.sop_class_uid, "SOP Class UID (0008,0016)", path);
  require_uid(header.study_uid, "Study Instance UID (0020,000D)", path);
  require_uid(header.series_uid, "Series Instance UID (0020,000E)", path);
  require_pixels_of_an_image(dataset, header, path);
  return header;
}

}  // namespace maxillo
