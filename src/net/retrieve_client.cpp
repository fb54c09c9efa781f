#include "net/retrieve_client.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcuid.h>

#include <chrono>

#include "core/error.h"
#include "core/temporary_folder.h"
#include "net/association_requestor.h"
#include "net/tls_layer.h"
#include "net/storage_classes.h"

namespace maxillo::net {
namespace {

// The C-GET model, and for every storage class we accept the role of storage SCP on this
// association (C-GET's sub-operations come back as C-STOREs to the requestor).
void propose(DcmSCU& scu) {
  OFList<OFString> plain;
  plain.push_back(UID_LittleEndianExplicitTransferSyntax);
  plain.push_back(UID_LittleEndianImplicitTransferSyntax);
  scu.addPresentationContext(UID_GETStudyRootQueryRetrieveInformationModel, plain);
  for (const auto& syntax : accepted_transfer_syntaxes())
    for (const auto& storage : accepted_storage_classes()) {
      OFList<OFString> one;
      one.push_back(syntax.c_str());
      scu.addPresentationContext(storage.sop_class_uid.c_str(), one, ASC_SC_ROLE_SCP);
    }
}

}  // namespace

RetrieveReport retrieve_study(const DicomPeer& peer, const std::string& study_uid, Archive& archive,
                              const RetrieveOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const TemporaryFolder scratch("maxillo-retrieve");
  const auto tls = requestor_tls(options.tls);  // outlives the association
  Requestor scu;
  configure_requestor(scu, peer, options.calling_ae, options.timeout_seconds, tls.get());
  scu.setStorageMode(DCMSCU_STORAGE_BIT_PRESERVING);
  scu.setStorageDir(scratch.path().c_str());
  propose(scu);
  request_association(scu, peer);
  const T_ASC_PresentationContextID context =
      require_context(scu, peer, UID_GETStudyRootQueryRetrieveInformationModel, "C-GET (Study Root)");
  DcmDataset keys;
  keys.putAndInsertString(DCM_QueryRetrieveLevel, "STUDY");
  keys.putAndInsertString(DCM_StudyInstanceUID, study_uid.c_str());
  OFList<RetrieveResponse*> responses;
  const OFCondition got = scu.sendCGETRequest(context, &keys, &responses);
  scu.releaseAssociation();
  RetrieveReport report;
  Uint16 final_status = 0;
  for (RetrieveResponse* response : responses) {
    final_status = response->m_status;
    report.failed_by_peer = response->m_numberOfFailedSubops;
    delete response;
  }
  if (got.bad()) throw Error(ErrorCode::kNetwork, to_string(peer), std::string("C-GET failed: ") + got.text());
  if (final_status != STATUS_GET_Success && (final_status & 0xf000) != 0xb000)
    throw Error(ErrorCode::kNetwork, to_string(peer), "C-GET ended with status " + std::to_string(final_status));
  for (const auto& entry : std::filesystem::directory_iterator(scratch.path())) report.received += entry.is_regular_file();
  ImportOptions import;
  import.progress = options.progress;
  if (report.received > 0) report.imported = archive.import_paths({scratch.path()}, import);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return report;
}

}  // namespace maxillo::net
