#pragma once
// C-FIND at study level (Study Root): what a PACS holds for a patient, a name, a date range or a
// modality. The peer's answers are returned as they came; matching is the peer's (DICOM wildcard
// rules: '*' and '?' in names and IDs, "20240101-20241231" for a date range).
#include <string>
#include <vector>

#include "net/dicom_peer.h"
#include "net/tls_options.h"

namespace maxillo::net {

struct StudyQuery {
  std::string patient_id;    // empty: any
  std::string patient_name;  // DICOM person name, wildcards allowed
  std::string study_date;    // YYYYMMDD or a range
  std::string modality;      // e.g. CT (Modalities in Study)
  std::string study_uid;
};

struct StudyMatch {
  std::string patient_id, patient_name, study_uid, study_date, study_description, modalities, accession;
  int instances = 0;  // Number of Study Related Instances, when the peer gives it
};

struct QueryOptions {
  std::string calling_ae = "MAXILLO";
  int timeout_seconds = 30;
  TlsOptions tls;
};

// Error(kNetwork) naming the peer when the association fails or the peer answers with a failure.
std::vector<StudyMatch> find_studies(const DicomPeer& peer, const StudyQuery& query, const QueryOptions& options = {});

}  // namespace maxillo::net
