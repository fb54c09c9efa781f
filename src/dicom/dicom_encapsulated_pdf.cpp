#include "dicom/dicom_encapsulated_pdf.h"

#include <dcmtk/dcmdata/dctk.h>

#include <algorithm>
#include <cassert>
#include <cctype>
#include <cstring>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/sha256.h"
#include "core/utc_time.h"
#include "core/version.h"
#include "dicom/dicom_uid.h"
#include "dicom/put_attribute.h"

namespace maxillo {
namespace {

// DICOM DA and TM of the document's own /CreationDate (D:YYYYMMDDHHmmSS), or empty (both are
// type 2): never the clock, so the same PDF always gives the same file, as it gives the same SOP
// Instance UID, and filing a report twice is "already archived", not a conflict.
std::pair<std::string, std::string> creation_date_time(std::span<const std::byte> pdf) {
  const std::string_view text(reinterpret_cast<const char*>(pdf.data()), pdf.size());
  const auto at = text.find("/CreationDate (D:");
  if (at == std::string_view::npos) return {};
  const auto digits = text.substr(at + 17, 14);
  if (digits.size() < 8 || !std::all_of(digits.begin(), digits.begin() + 8,
                                        [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    return {};
  size_t time_digits = 8;
  while (time_digits < digits.size() && std::isdigit(static_cast<unsigned char>(digits[time_digits]))) ++time_digits;
  return {std::string(digits.substr(0, 8)), std::string(digits.substr(8, (time_digits - 8) / 2 * 2))};
}

void put_patient_and_study(DcmDataset& d, const EncapsulatedReport& r) {
  put(d, DCM_SpecificCharacterSet, "ISO_IR 192");  // UTF-8
  put(d, DCM_PatientName, r.patient.name);
  put(d, DCM_PatientID, r.patient.patient_id);
  put(d, DCM_PatientBirthDate, r.patient.birth_date);
  put(d, DCM_PatientSex, r.patient.sex);
  put(d, DCM_StudyInstanceUID, r.study.study_uid);
  put(d, DCM_StudyDate, r.study.date);
  put(d, DCM_StudyTime, r.study.time);
  put(d, DCM_AccessionNumber, r.study.accession);
  put(d, DCM_StudyDescription, r.study.description);
  put(d, DCM_ReferringPhysicianName, "");
  put(d, DCM_StudyID, "");
}

void put_document(DcmDataset& d, const EncapsulatedReport& r, std::span<const std::byte> pdf, const std::string& sop) {
  const auto [date, time] = creation_date_time(pdf);
  put(d, DCM_SOPClassUID, UID_EncapsulatedPDFStorage);
  put(d, DCM_SOPInstanceUID, sop);
  put(d, DCM_Modality, "DOC");
  put(d, DCM_SeriesInstanceUID, derived_uid("maxillo reports of study " + r.study.study_uid));
  put(d, DCM_SeriesNumber, std::to_string(r.series_number));
  put(d, DCM_SeriesDescription, r.series_description);
  put(d, DCM_Manufacturer, "maxillo");
  put(d, DCM_SoftwareVersions, kVersion);
  put(d, DCM_ConversionType, "SD");  // synthetic document
  put(d, DCM_InstanceNumber, "1");
  put(d, DCM_ContentDate, date);
  put(d, DCM_ContentTime, time);
  put(d, DCM_AcquisitionDateTime, date + time);
  put(d, DCM_BurnedInAnnotation, "YES");  // the PDF names the patient
  put(d, DCM_DocumentTitle, r.document_title);
  d.insertEmptyElement(DCM_ConceptNameCodeSequence);
  put(d, DCM_MIMETypeOfEncapsulatedDocument, "application/pdf");
  // OB values have even length: pad with one zero byte, as PS3.3 C.24.2.1 allows.
  std::vector<Uint8> value(pdf.size() + (pdf.size() % 2));
  std::memcpy(value.data(), pdf.data(), pdf.size());
  [[maybe_unused]] OFCondition status =
      d.putAndInsertUint8Array(DCM_EncapsulatedDocument, value.data(), static_cast<unsigned long>(value.size()));
  assert(status.good() && "cannot insert the encapsulated document");
}

}  // namespace

std::string write_encapsulated_pdf(std::span<const std::byte> pdf, const EncapsulatedReport& report,
                                   const std::filesystem::path& out) {
  const std::string sop = derived_uid("maxillo report " + sha256_hex(pdf));
  DcmFileFormat file;
  DcmDataset& dataset = *file.getDataset();
  put_patient_and_study(dataset, report);
  put_document(dataset, report, pdf, sop);

  auto temporary = temporary_sibling(out);
  OFCondition status = file.saveFile(temporary.c_str(), EXS_LittleEndianExplicit);
  if (status.bad() || std::rename(temporary.c_str(), out.c_str()) != 0) {
    std::filesystem::remove(temporary);
    throw Error(ErrorCode::kWriteFailed, out.string(), std::string("cannot write: ") + status.text());
  }
  return sop;
}

}  // namespace maxillo
