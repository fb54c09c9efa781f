#include "net/storage_server.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmnet/diutil.h>
#include <dcmtk/dcmnet/scpthrd.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <thread>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "archive/archive.h"
#include "archive/archive_location.h"
#include "archive/instance_source.h"
#include "core/error.h"
#include "core/log.h"
#include "net/association_pool.h"
#include "net/group_commit.h"
#include "net/no_nagle_delay.h"
#include "net/pending_studies.h"
#include "net/stable_studies.h"
#include "net/stable_study_action.h"
#include "net/storage_contexts.h"
#include "net/tls_layer.h"

namespace maxillo::net {

// Longest wait for an association request after a peer has connected (see configure()).
constexpr int kAssociationRequestSeconds = 3;

struct StorageServer::Shared {
  StorageServerOptions options;
  std::filesystem::path incoming;  // ARCHIVE/incoming: datasets being received
  std::atomic<int64_t> associations{0}, refused{0}, stored{0}, already_archived{0}, failed{0};
  std::atomic<int64_t> next_file{0};
  std::atomic<bool> stop_requested{false};
  std::unique_ptr<StableStudies> stable;    // set when there is a stable-study action
  std::unique_ptr<PendingStudies> pending;  // ... and the actions owed, kept across restarts
  std::atomic<int64_t> stable_actions{0}, failed_actions{0};
  std::unique_ptr<DcmTLSTransportLayer> tls;  // set when serving DICOM TLS
  std::unique_ptr<GroupCommit> commit;        // archives what the associations receive
};

namespace {

// The C-STORE status for one received file's import, and the reason for a failure.
struct StoreAnswer {
  Uint16 status = STATUS_Success;
  std::string reason;
  bool already_archived = false;  // success: the same bytes were archived before
};

StoreAnswer answer_for(const GroupCommit::Result& result) {
  if (result.outcome == ImportOutcome::Imported) return {};
  if (result.outcome == ImportOutcome::AlreadyArchived) return {STATUS_Success, "", true};
  // Input errors (20-39) and conflicts are the sender's data; anything else is ours.
  const int exit_code = exit_code_for(result.code);
  const bool senders_data = (exit_code >= 20 && exit_code < 40) || result.outcome == ImportOutcome::Conflict;
  return {Uint16(senders_data ? STATUS_STORE_Error_CannotUnderstand : STATUS_STORE_Refused_OutOfResources),
          result.reason};
}

// One association: checks who calls, archives each C-STORE before answering it.
class ArchivingSCP : public DcmThreadSCP {
 public:
  explicit ArchivingSCP(StorageServer::Shared& shared) : shared_(shared) {}

 protected:
  OFBool checkCalledAETitleAccepted(const OFString& called_ae) override {
    if (called_ae == shared_.options.ae_title.c_str()) return OFTrue;
    log::warning("serve: association refused: called AE title '", called_ae.c_str(), "' is not ours");
    ++shared_.refused;
    return OFFalse;
  }

  OFBool checkCallingAETitleAccepted(const OFString& calling_ae) override {
    const std::string address = getPeerIP().c_str();
    if (is_allowed(shared_.options.allowed, calling_ae.c_str(), address)) return OFTrue;
    log::warning("serve: association refused: calling AE title '", calling_ae.c_str(), "' from ", address,
                 " is not allowed (--allow)");
    ++shared_.refused;
    return OFFalse;
  }

  // Contexts we will refuse, with the reason (DCMTK's own log is silenced): one line, and the
  // list at -v. A sender such as storescu proposes a hundred classes it may never use.
  void notifyAssociationRequest(const T_ASC_Parameters& request, DcmSCPActionType& action) override {
    DcmThreadSCP::notifyAssociationRequest(request, action);
    const auto refusals = refused_contexts(request);
    if (refusals.empty()) return;
    log::info("serve: ", request.DULparams.callingAPTitle, " proposed ", refusals.size(),
              " presentation contexts we do not accept (-v lists them)");
    for (const auto& refusal : refusals)
      log::debug("serve: ", request.DULparams.callingAPTitle, " proposed ", refusal, " (refused)");
  }

  void notifyAssociationAcknowledge() override {
    ++shared_.associations;
    calling_ae_ = getPeerAETitle().c_str();
    source_label_ = network_source(calling_ae_, getPeerIP().c_str());
    stored_ = already_ = failed_ = 0;
    log::info("serve: association from ", calling_ae_, " (", getPeerIP().c_str(), ")");
  }

  void notifyAssociationTermination() override {
    if (!calling_ae_.empty())
      log::info("serve: association from ", calling_ae_, " ended: ", stored_, " instances archived, ", already_,
                " already archived, ", failed_, " refused");
    calling_ae_.clear();
    archive_.reset();
  }

  OFCondition handleIncomingCommand(T_DIMSE_Message* message, const DcmPresentationContextInfo& context) override {
    if (message->CommandField != DIMSE_C_STORE_RQ) return DcmThreadSCP::handleIncomingCommand(message, context);
    T_DIMSE_C_StoreRQ& request = message->msg.CStoreRQ;
    const std::filesystem::path file = incoming_file();
    const OFCondition received = receiveSTORERequest(request, context.presentationContextID, file.c_str());
    if (received.bad()) {
      // The peer went away or broke the protocol mid-transfer: nothing was archived, and the
      // association ends (DcmSCP aborts it on a bad condition).
      std::filesystem::remove(file);
      log::warning("serve: a C-STORE from ", calling_ae_, " was not received whole: ", received.text());
      ++shared_.failed;
      return received;
    }
    const StoreAnswer answer = archive_file(file, request.AffectedSOPInstanceUID);
    std::filesystem::remove(file);
    if (answer.status != STATUS_Success) {
      ++failed_;
      ++shared_.failed;
      log::warning("serve: C-STORE from ", calling_ae_, " refused (status 0x", std::hex, answer.status, std::dec,
                   "): ", answer.reason);
      DcmDataset detail;
      detail.putAndInsertString(DCM_ErrorComment, answer.reason.substr(0, 64).c_str());
      return sendSTOREResponse(context.presentationContextID, request.MessageID, request.AffectedSOPClassUID,
                               request.AffectedSOPInstanceUID, answer.status, &detail);
    }
    ++(answer.already_archived ? already_ : stored_);
    return sendSTOREResponse(context.presentationContextID, request, STATUS_Success);
  }

 private:
  std::filesystem::path incoming_file() {
    return shared_.incoming /
           ("received-" + std::to_string(getpid()) + "-" + std::to_string(++shared_.next_file) + ".dcm");
  }

  std::string study_of(const std::string& sop_instance_uid) const {
    const ResolvedItem item = archive_->resolve(sop_instance_uid);
    if (item.kind != ItemKind::Instance)
      throw Error(ErrorCode::kNotFound, sop_instance_uid, "not an archived instance");
    const auto instance = archive_->instance(item.id);
    return archive_->study(archive_->series_by_id(instance->series)->study)->study_uid;
  }

  // Archived with whatever other associations have received meanwhile (net/group_commit.h).
  StoreAnswer archive_file(const std::filesystem::path& file, const std::string& sop_instance_uid) {
    const GroupCommit::Result result = shared_.commit->archive(file, source_label_);
    shared_.stored += result.outcome == ImportOutcome::Imported;
    shared_.already_archived += result.outcome == ImportOutcome::AlreadyArchived;
    if (result.outcome == ImportOutcome::Imported && shared_.stable) note_study_change(sop_instance_uid);
    return answer_for(result);
  }

  // The instance is archived whatever happens here: a failure to find its study costs the
  // stable-study action, never the C-STORE's success.
  void note_study_change(const std::string& sop_instance_uid) {
    try {
      if (!archive_) archive_.emplace(Archive::open(shared_.options.archive));
      const std::string study = study_of(sop_instance_uid);
      shared_.stable->archived(study, StableStudies::Clock::now());
      shared_.pending->add(study);  // durable before the C-STORE is answered
    } catch (const std::exception& error) {
      log::warning("serve: an archived instance's study was not found, no stable-study action for it: ", error.what());
    }
  }

  StorageServer::Shared& shared_;
  std::optional<Archive> archive_;  // this association's, to look up studies for the stable-study action
  std::string calling_ae_;
  std::string source_label_;  // each instance's recorded source: dicom://AE@ADDRESS
  int64_t stored_ = 0, already_ = 0, failed_ = 0;
};

void configure(DcmSCPConfig& config, const StorageServerOptions& options) {
  no_nagle_delay();
  config.setAETitle(options.ae_title.c_str());
  config.setPort(options.port);
  config.setRespondWithCalledAETitle(OFFalse);
  config.setHostLookupEnabled(OFFalse);
  // Non-blocking accept with a 1 s timeout: the listening loop notices stop() within a second.
  config.setConnectionBlockingMode(DUL_NOBLOCK);
  config.setConnectionTimeout(1);
  config.setDIMSEBlockingMode(DIMSE_NONBLOCKING);
  config.setDIMSETimeout(Uint32(options.timeout_seconds));
  // The listening loop (net/association_pool.h) reads each association request itself, waiting up to the ACSE
  // timeout for the first PDU: a peer that connects and says nothing would hold up every other
  // caller that long. A real peer sends its request as soon as it has connected, and the other
  // association-level exchanges (acknowledge, release) are as quick, so this bound is short.
  config.setACSETimeout(Uint32(std::min(options.timeout_seconds, kAssociationRequestSeconds)));
  config.setMaxReceivePDULength(ASC_DEFAULTMAXPDU * 8);
  accept_verification(config);
  accept_storage(config);
}

// What a killed server left in incoming/ was never acknowledged: the sender still has it.
void clear_incoming(const std::filesystem::path& incoming) {
  std::filesystem::create_directories(incoming);
  for (const auto& entry : std::filesystem::directory_iterator(incoming)) std::filesystem::remove(entry.path());
}

// The server's own check of a stable study's case (options.check_stable_case). A study with no
// case, or whose case has no volume to check, is no error of the server's.
void check_stable_case(const StorageServerOptions& options, const std::string& study_uid) {
  const auto case_id = default_case_of_study(options.archive, study_uid);
  if (!case_id) return;
  try {
    Archive archive = Archive::open(options.archive);
    options.check_stable_case(archive, *case_id);
  } catch (const std::exception& error) {
    log::debug("serve: case:", *case_id, ": not checked: ", error.what());
  }
}

// DCMTK binds the port inside its listening loop, with no word before: try the bind here first
// (with SO_REUSEADDR, as DCMTK does), so that a taken port is an error before anything says
// "listening". Another process could take it in between; the loop then fails as before.
void require_port_free(uint16_t port) {
  const int probe = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (probe < 0) return;
  const int on = 1;
  ::setsockopt(probe, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_ANY);
  address.sin_port = htons(port);
  const bool bound = ::bind(probe, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0;
  const int error_number = errno;
  ::close(probe);
  if (!bound)
    throw Error(ErrorCode::kWriteFailed, "port " + std::to_string(port),
                std::string("cannot listen: ") + std::strerror(error_number));
}

}  // namespace

StorageServer::StorageServer(StorageServerOptions options) : shared_(std::make_unique<Shared>()) {
  check_ae_title(options.ae_title, "--aet");
  if (options.port == 0) throw Error(ErrorCode::kUsage, "--port", "the port must be from 1 to 65535");
  if (options.max_associations < 1 || options.max_associations > 64)
    throw Error(ErrorCode::kUsage, "--max-associations", "from 1 to 64");
  if (options.timeout_seconds < 1 || options.timeout_seconds > 3600)
    throw Error(ErrorCode::kUsage, "--timeout", "from 1 to 3600 seconds");
  Archive::open(options.archive, OpenMode::CreateIfMissing);  // create it, or refuse a damaged one, before listening
  if (options.spool.empty()) {
    if (names_index_server(options.archive.string()))
      throw Error(ErrorCode::kUsage, "--spool",
                  "an archive on a PostgreSQL server needs --spool FOLDER: this node's folder for files being "
                  "received and owed stable-study actions");
    options.spool = options.archive;
  }
  if (!options.on_stable_study.empty() || options.check_stable_case) {
    if (options.stable_seconds < 1 || options.stable_seconds > 86400)
      throw Error(ErrorCode::kUsage, "--stable-seconds", "from 1 to 86400 seconds");
    shared_->stable = std::make_unique<StableStudies>(std::chrono::seconds(options.stable_seconds));
    shared_->pending = std::make_unique<PendingStudies>(options.spool / "serve" / "pending-stable-studies");
    // Actions owed from before a stop or a crash: due after a full quiet period from now.
    const auto owed = shared_->pending->studies();
    for (const auto& study : owed) shared_->stable->archived(study, StableStudies::Clock::now());
    if (!owed.empty()) log::info("serve: ", owed.size(), " studies still owe their stable-study action");
  }
  shared_->tls = acceptor_tls(options.tls);
  shared_->commit = std::make_unique<GroupCommit>(options.archive);
  shared_->incoming = options.spool / "incoming";
  clear_incoming(shared_->incoming);
  shared_->options = std::move(options);
}

StorageServer::~StorageServer() = default;

void StorageServer::run(const std::function<void()>& on_listening) {
  require_port_free(shared_->options.port);
  DcmSCPConfig config;
  configure(config, shared_->options);
  if (shared_->tls) config.setTransportLayer(shared_->tls.get());
  std::atomic<bool> listening{true};
  std::thread stable_actions([&] {
    if (!shared_->stable) return;
    while (listening) {
      for (const auto& study : shared_->stable->take_due(StableStudies::Clock::now())) {
        if (shared_->options.check_stable_case) check_stable_case(shared_->options, study);
        if (!shared_->options.on_stable_study.empty()) {
          const int status = run_stable_study_action(shared_->options.on_stable_study, shared_->options.archive, study);
          ++shared_->stable_actions;
          if (status != 0) ++shared_->failed_actions;
        }
        shared_->pending->remove_if_settled(study, [&] { return shared_->stable->changed_since_due(study); });
      }
      for (int tick = 0; tick < 10 && listening; ++tick) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  });
  const auto serve_association = [this](T_ASC_Association* association, const DcmSharedSCPConfig& shared_config) {
    ArchivingSCP scp(*shared_);
    scp.setSharedConfig(shared_config);
    scp.run(association);
  };
  // A connection that fails before its association (a failed TLS handshake) is logged and
  // counted as a refusal, like a refused AE title.
  const auto receive_failure = [this](const std::string& reason) {
    log::warning("serve: a connection failed before its association: ", reason);
    ++shared_->refused;
  };
  AssociationPool pool(config, shared_->options.max_associations, serve_association, receive_failure);
  if (on_listening) on_listening();
  const OFCondition result = pool.listen(shared_->stop_requested);
  listening = false;
  stable_actions.join();
  if (result.bad())
    throw Error(ErrorCode::kWriteFailed, "port " + std::to_string(shared_->options.port),
                std::string("cannot listen: ") + result.text());
}

void StorageServer::stop() { shared_->stop_requested = true; }

StorageServerCounts StorageServer::counts() const {
  return {shared_->associations, shared_->refused,        shared_->stored,        shared_->already_archived,
          shared_->failed,       shared_->stable_actions, shared_->failed_actions};
}

}  // namespace maxillo::net
