#include "net/query_client.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcuid.h>

#include <cstdlib>

#include "core/error.h"
#include "net/association_requestor.h"
#include "net/tls_layer.h"

namespace maxillo::net {
namespace {

// The query identifier: the keys we match on, and empty return keys for what we want back.
void build_identifier(DcmDataset& keys, const StudyQuery& query) {
  keys.putAndInsertString(DCM_QueryRetrieveLevel, "STUDY");
  keys.putAndInsertString(DCM_PatientID, query.patient_id.c_str());
  keys.putAndInsertString(DCM_PatientName, query.patient_name.c_str());
  keys.putAndInsertString(DCM_StudyDate, query.study_date.c_str());
  keys.putAndInsertString(DCM_ModalitiesInStudy, query.modality.c_str());
  keys.putAndInsertString(DCM_StudyInstanceUID, query.study_uid.c_str());
  keys.putAndInsertString(DCM_StudyDescription, "");
  keys.putAndInsertString(DCM_AccessionNumber, "");
  keys.putAndInsertString(DCM_NumberOfStudyRelatedInstances, "");
}

std::string text(DcmDataset* dataset, const DcmTagKey& tag) {
  OFString value;
  if (dataset) dataset->findAndGetOFStringArray(tag, value);
  return value.c_str();
}

StudyMatch match_of(DcmDataset* dataset) {
  StudyMatch match;
  match.patient_id = text(dataset, DCM_PatientID);
  match.patient_name = text(dataset, DCM_PatientName);
  match.study_uid = text(dataset, DCM_StudyInstanceUID);
  match.study_date = text(dataset, DCM_StudyDate);
  match.study_description = text(dataset, DCM_StudyDescription);
  match.modalities = text(dataset, DCM_ModalitiesInStudy);
  match.accession = text(dataset, DCM_AccessionNumber);
  match.instances = std::atoi(text(dataset, DCM_NumberOfStudyRelatedInstances).c_str());
  return match;
}

}  // namespace

std::vector<StudyMatch> find_studies(const DicomPeer& peer, const StudyQuery& query, const QueryOptions& options) {
  const auto tls = requestor_tls(options.tls);  // outlives the association
  Requestor scu;
  configure_requestor(scu, peer, options.calling_ae, options.timeout_seconds, tls.get());
  OFList<OFString> syntaxes;
  syntaxes.push_back(UID_LittleEndianExplicitTransferSyntax);
  syntaxes.push_back(UID_LittleEndianImplicitTransferSyntax);
  scu.addPresentationContext(UID_FINDStudyRootQueryRetrieveInformationModel, syntaxes);
  request_association(scu, peer);
  const T_ASC_PresentationContextID context =
      require_context(scu, peer, UID_FINDStudyRootQueryRetrieveInformationModel, "C-FIND (Study Root)");
  DcmDataset keys;
  build_identifier(keys, query);
  OFList<QRResponse*> responses;
  const OFCondition found = scu.sendFINDRequest(context, &keys, &responses);
  scu.releaseAssociation();
  std::vector<StudyMatch> matches;
  Uint16 final_status = 0;
  for (QRResponse* response : responses) {
    if (response->m_status == STATUS_FIND_Pending_MatchesAreContinuing ||
        response->m_status == STATUS_FIND_Pending_WarningUnsupportedOptionalKeys)
      matches.push_back(match_of(response->m_dataset));
    else
      final_status = response->m_status;
    delete response;
  }
  if (found.bad()) throw Error(ErrorCode::kNetwork, to_string(peer), std::string("C-FIND failed: ") + found.text());
  if (final_status != STATUS_Success)
    throw Error(ErrorCode::kNetwork, to_string(peer), "C-FIND ended with status " + std::to_string(final_status));
  return matches;
}

}  // namespace maxillo::net
