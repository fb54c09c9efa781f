#pragma once
// The patient and the study as the archive indexes them (rows of db/001_initial.sql): the two
// records a DICOM instance made from the archive's contents needs (dicom_encapsulated_pdf.h),
// here below the archive so that the codec knows no archive. Plain values, no toolkit types;
// `id` fields are archive ids, which the codec never reads. archive/archive_records.h holds the
// other records and includes this.
#include <cstdint>
#include <string>

namespace maxillo {

struct PatientRecord {
  int64_t id = 0;
  std::string patient_id;  // protected health information: log at debug level only
  std::string name;        // DICOM person name, UTF-8
  std::string birth_date;  // YYYYMMDD or empty
  std::string sex;
  int64_t study_count = 0;
};

struct StudyRecord {
  int64_t id = 0;
  int64_t patient = 0;
  std::string study_uid;
  std::string date;  // YYYYMMDD
  std::string time;
  std::string description;
  std::string accession;
  int64_t series_count = 0;
};

}  // namespace maxillo
