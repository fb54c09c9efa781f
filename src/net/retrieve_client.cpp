#include "net/retrieve_client.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmnet/diutil.h>

#include <chrono>
#include <cstdio>
#include <optional>

#include "archive/instance_source.h"
#include "core/error.h"
#include "core/progress.h"
#include "core/temporary_folder.h"
#include "net/association_requestor.h"
#include "net/move_destination.h"
#include "net/storage_classes.h"
#include "net/tls_layer.h"

namespace maxillo::net {
namespace {

// A requestor that draws the retrieve's progress from the peer's responses: each pending one
// counts the sub-operations done and remaining (the total is known from the first).
class RetrieveRequestor : public Requestor {
 public:
  explicit RetrieveRequestor(ProgressDisplay display) : display_(display) {}

  OFCondition handleCGETResponse(const T_ASC_PresentationContextID context, RetrieveResponse* response,
                                 OFBool& continue_session) override {
    note(*response);
    return Requestor::handleCGETResponse(context, response, continue_session);
  }
  OFCondition handleMOVEResponse(const T_ASC_PresentationContextID context, RetrieveResponse* response,
                                 OFBool& wait_for_next) override {
    note(*response);
    return Requestor::handleMOVEResponse(context, response, wait_for_next);
  }
  void finish() {
    if (progress_) progress_->finish();
  }

 private:
  void note(const RetrieveResponse& response) {
    const size_t done =
        response.m_numberOfCompletedSubops + response.m_numberOfFailedSubops + response.m_numberOfWarningSubops;
    if (!progress_) progress_.emplace("retrieve", done + response.m_numberOfRemainingSubops, display_);
    if (done > shown_) progress_->advance(done - shown_);
    shown_ = std::max(shown_, done);
  }

  ProgressDisplay display_;
  std::optional<Progress> progress_;
  size_t shown_ = 0;
};

// C-GET: the model, and for every storage class the role of storage SCP on this association
// (C-GET's sub-operations come back as C-STOREs to the requestor).
void propose_get(DcmSCU& scu) {
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

// C-MOVE: the model, and verification beside it, so that a peer without C-MOVE still accepts the
// association and we can say what it lacks (a peer accepting no context rejects it outright).
void propose_move(DcmSCU& scu) {
  OFList<OFString> plain;
  plain.push_back(UID_LittleEndianExplicitTransferSyntax);
  plain.push_back(UID_LittleEndianImplicitTransferSyntax);
  scu.addPresentationContext(UID_MOVEStudyRootQueryRetrieveInformationModel, plain);
  scu.addPresentationContext(UID_VerificationSOPClass, plain);
}

// The last response's status and failed count; Error(kNetwork) unless success or a warning.
void check_outcome(const OFCondition& sent, OFList<RetrieveResponse*>& responses, const DicomPeer& peer,
                   const std::string& service, RetrieveReport& report) {
  Uint16 final_status = 0;
  for (RetrieveResponse* response : responses) {
    final_status = response->m_status;
    report.failed_by_peer = response->m_numberOfFailedSubops;
    report.sent_by_peer = response->m_numberOfCompletedSubops;
    delete response;
  }
  if (sent.bad()) throw Error(ErrorCode::kNetwork, to_string(peer), service + " failed: " + sent.text());
  if (final_status != STATUS_Success && (final_status & 0xf000) != 0xb000)
    throw Error(ErrorCode::kNetwork, to_string(peer),
                service + " ended with status " + status_text(service, final_status));
}

// Asks the peer for the study and waits for its final response.
void request_study(const DicomPeer& peer, const std::string& study_uid, const std::filesystem::path& scratch,
                   const RetrieveOptions& options, RetrieveReport& report) {
  const bool by_move = options.move_port != 0;
  const auto tls = requestor_tls(options.tls);  // outlives the association
  RetrieveRequestor scu(options.progress);
  configure_requestor(scu, peer, options.calling_ae, options.timeout_seconds, tls.get());
  if (by_move) {
    propose_move(scu);
  } else {
    scu.setStorageMode(DCMSCU_STORAGE_BIT_PRESERVING);
    scu.setStorageDir(scratch.c_str());
    propose_get(scu);
  }
  request_association(scu, peer);
  const char* model =
      by_move ? UID_MOVEStudyRootQueryRetrieveInformationModel : UID_GETStudyRootQueryRetrieveInformationModel;
  const std::string service = by_move ? "C-MOVE" : "C-GET";
  const T_ASC_PresentationContextID context = require_context(scu, peer, model, service + " (Study Root)");
  DcmDataset keys;
  keys.putAndInsertString(DCM_QueryRetrieveLevel, "STUDY");
  keys.putAndInsertString(DCM_StudyInstanceUID, study_uid.c_str());
  OFList<RetrieveResponse*> responses;
  const OFCondition sent = by_move ? scu.sendMOVERequest(context, options.calling_ae.c_str(), &keys, &responses)
                                   : scu.sendCGETRequest(context, &keys, &responses);
  scu.finish();
  scu.releaseAssociation();
  check_outcome(sent, responses, peer, service, report);
}

}  // namespace

std::string status_text(const std::string& service, uint16_t status) {
  char code[8];
  std::snprintf(code, sizeof code, "0x%04X", unsigned(status));
  const char* meaning = service == "C-MOVE" ? DU_cmoveStatusString(status) : DU_cgetStatusString(status);
  return std::string(code) + " (" + meaning + ")";
}

RetrieveReport retrieve_study(const DicomPeer& peer, const std::string& study_uid, Archive& archive,
                              const RetrieveOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const TemporaryFolder scratch("maxillo-retrieve");
  RetrieveReport report;
  {
    // C-MOVE delivers on associations of the peer's own, to us listening for the duration.
    std::optional<MoveDestination> destination;
    if (options.move_port != 0)
      destination.emplace(scratch.path(), options.calling_ae, options.move_port, peer.ae_title, options.timeout_seconds,
                          options.tls);
    request_study(peer, study_uid, scratch.path(), options, report);
  }
  for (const auto& entry : std::filesystem::directory_iterator(scratch.path()))
    report.received += entry.is_regular_file();
  ImportOptions import;
  import.progress = options.progress;
  import.source_label = network_source(peer.ae_title, peer.host);
  if (report.received > 0) report.imported = archive.import_paths({scratch.path()}, import);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return report;
}

}  // namespace maxillo::net
