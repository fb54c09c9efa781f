#include "dicom/dicom_deidentify.h"

#include <dcmtk/dcmdata/dctk.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/sha256.h"
#include "dicom/dicom_header.h"
#include "dicom/dicom_uid.h"

namespace maxillo {
namespace {

// PS3.15 E.1 actions X (remove) and Z/D for type 2 attributes (kept, emptied).
const DcmTagKey kRemoved[] = {DCM_PatientAddress,
                              DCM_PatientTelephoneNumbers,
                              DCM_OtherPatientIDsSequence,
                              DCM_RETIRED_OtherPatientIDs,
                              DCM_OtherPatientNames,
                              DCM_PatientMotherBirthName,
                              DCM_RETIRED_MedicalRecordLocator,
                              DCM_Occupation,
                              DCM_AdditionalPatientHistory,
                              DCM_PatientComments,
                              DCM_PatientBirthTime,
                              DCM_PatientBirthName,
                              DCM_InstitutionName,
                              DCM_InstitutionAddress,
                              DCM_InstitutionalDepartmentName,
                              DCM_ReferringPhysicianAddress,
                              DCM_ReferringPhysicianTelephoneNumbers,
                              DCM_PerformingPhysicianName,
                              DCM_OperatorsName,
                              DCM_PhysiciansOfRecord,
                              DCM_NameOfPhysiciansReadingStudy,
                              DCM_RequestingPhysician,
                              DCM_DeviceSerialNumber,
                              DCM_StationName,
                              DCM_RequestAttributesSequence,
                              DCM_ReferencedPatientSequence,
                              DCM_ReferencedStudySequence,
                              DCM_ReferencedPerformedProcedureStepSequence,
                              DCM_PerformedProcedureStepID,
                              DCM_ScheduledProcedureStepID,
                              DCM_RequestedProcedureID,
                              DCM_RETIRED_StudyComments,
                              DCM_ImageComments,
                              DCM_ProtocolName,
                              DCM_IssuerOfPatientID,
                              DCM_MilitaryRank,
                              DCM_BranchOfService,
                              DCM_RegionOfResidence,
                              DCM_CountryOfResidence,
                              DCM_PatientInsurancePlanCodeSequence,
                              DCM_CurrentPatientLocation,
                              DCM_PatientInstitutionResidence};
const DcmTagKey kEmptied[] = {DCM_PatientBirthDate, DCM_ReferringPhysicianName, DCM_AccessionNumber, DCM_StudyID};
const DcmTagKey kReplacedUids[] = {DCM_StudyInstanceUID, DCM_SeriesInstanceUID, DCM_SOPInstanceUID,
                                   DCM_FrameOfReferenceUID};

// The value's bytes as stored, unrepaired (unlike dicom_header.cpp's text_of, which makes text
// valid UTF-8 for the index): the originals keyed here are UIDs and the Patient ID.
std::string raw_text_of(DcmItem& item, const DcmTagKey& tag) {
  OFString value;
  return item.findAndGetOFStringArray(tag, value).good() ? std::string(value.c_str()) : std::string();
}

void remove_private_attributes(DcmDataset& dataset) {
  for (unsigned long i = dataset.card(); i-- > 0;)
    if (dataset.getElement(i)->getTag().isPrivate()) delete dataset.remove(i);
}

std::string replace_uids(DcmDataset& dataset, DcmMetaInfo& meta, std::string_view secret) {
  for (const auto& tag : kReplacedUids) {
    std::string original = raw_text_of(dataset, tag);
    if (!original.empty()) dataset.putAndInsertString(tag, pseudonymous_uid(secret, original).c_str());
  }
  std::string sop = raw_text_of(dataset, DCM_SOPInstanceUID);
  meta.putAndInsertString(DCM_MediaStorageSOPInstanceUID, sop.c_str());
  return sop;
}

void replace_identity(DcmDataset& dataset, std::string_view secret) {
  std::string pseudonym = pseudonym_for(secret, raw_text_of(dataset, DCM_PatientID));
  dataset.putAndInsertString(DCM_PatientID, pseudonym.c_str());
  dataset.putAndInsertString(DCM_PatientName, pseudonym.c_str());
  for (const auto& tag : kRemoved) delete dataset.remove(tag);
  for (const auto& tag : kEmptied)
    if (dataset.tagExists(tag)) dataset.putAndInsertString(tag, "");
  dataset.putAndInsertString(DCM_PatientIdentityRemoved, "YES");
  dataset.putAndInsertString(DCM_DeidentificationMethod,
                             "maxillo: PS3.15 E.1 basic profile; longitudinal dates and patient characteristics "
                             "retained; keyed-hash pseudonyms and UIDs");
}

// What the profile cannot clean must not leave as if it were clean (PS3.15 E.1: such content is
// removed or cleaned, never passed on): an encapsulated document (a consultation report as
// Encapsulated PDF names the patient on its first page), and pixels marked as carrying burnt-in
// text.
void refuse_identity_beyond_reach(DcmDataset& dataset, const std::filesystem::path& source) {
  if (dataset.tagExists(DCM_EncapsulatedDocument))
    throw Error(ErrorCode::kCannotDeidentify, source.string(),
                "an encapsulated document (" + raw_text_of(dataset, DCM_MIMETypeOfEncapsulatedDocument) +
                    ") carries the patient's identity inside the document, where de-identification cannot reach it");
  if (raw_text_of(dataset, DCM_BurnedInAnnotation) == "YES")
    throw Error(ErrorCode::kCannotDeidentify, source.string(),
                "Burned In Annotation is YES: the pixels carry text that de-identification does not remove");
}

}  // namespace

std::string pseudonym_for(std::string_view secret, std::string_view patient_id) {
  Sha256 hash;
  hash.update(secret);
  hash.update("\npatient\n");
  hash.update(patient_id);
  return "ANON-" + hash.hex_digest().substr(0, 12);
}

std::string pseudonymous_uid(std::string_view secret, std::string_view uid) {
  return derived_uid(std::string(secret) + "\nuid\n" + std::string(uid));
}

std::string write_deidentified_copy(const std::filesystem::path& source, const std::filesystem::path& target,
                                    std::string_view secret) {
  initialise_dicom_toolkit();
  DcmFileFormat file;
  OFCondition status = file.loadFile(source.c_str());
  if (status.bad()) throw Error(ErrorCode::kNotDicom, source.string(), std::string("cannot read: ") + status.text());
  DcmDataset& dataset = *file.getDataset();
  refuse_identity_beyond_reach(dataset, source);
  replace_identity(dataset, secret);
  remove_private_attributes(dataset);
  std::string sop = replace_uids(dataset, *file.getMetaInfo(), secret);

  auto temporary = temporary_sibling(target);
  status = file.saveFile(temporary.c_str(), EXS_Unknown);  // keeps the original transfer syntax
  if (status.bad() || std::rename(temporary.c_str(), target.c_str()) != 0) {
    std::filesystem::remove(temporary);
    throw Error(ErrorCode::kWriteFailed, target.string(), std::string("cannot write: ") + status.text());
  }
  return sop;
}

}  // namespace maxillo
