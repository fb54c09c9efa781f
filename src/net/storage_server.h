#pragma once
// The DICOM storage server behind `maxillo serve`: C-ECHO and C-STORE from the peers allowed to
// call, every received instance archived through Archive::import_paths (hashed, deduplicated by
// SOP Instance UID, atomic, identity flags), as `maxillo import` would archive the same file.
//
// A C-STORE is answered with success only after the object and its index row are durable (the
// import's sync and commit); anything else is answered with a failure status and a reason in
// the Error Comment, never a success. Several associations are served at once, one thread each,
// up to max_associations; the files they receive meanwhile are archived together, one sync and
// one commit for all (net/group_commit.h). A peer silent for timeout_seconds is dropped without
// holding up the others. stop() lets the associations in flight finish, then run() returns.
//
// Stable studies (options.on_stable_study): a thread looks once a second for studies quiet for
// stable_seconds (net/stable_studies.h) and runs the command for each, one at a time. The studies
// whose action is owed are kept in ARCHIVE/serve/ (net/pending_studies.h): after a stop or a
// crash, a restarted server runs them after a full quiet period.
// options.check_stable_case runs first for each of them, in the server.
//
// With TLS (options.tls) every association is TLS; a caller that does not speak it, or whose
// certificate is not trusted, fails the handshake and never reaches the AE title checks.
//
// Received datasets are written bit for bit (as the peer encoded them) into ARCHIVE/incoming/
// and removed once archived or refused; what a killed server leaves there was never
// acknowledged and is removed at the next start.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "archive/archive.h"
#include "net/dicom_peer.h"
#include "net/tls_options.h"

namespace maxillo::net {

struct StorageServerOptions {
  std::filesystem::path archive;  // an existing archive, or a folder to create one in
  // This node's own folder for files being received (incoming/) and owed stable-study actions
  // (serve/): the archive's folder when empty. An archive on a PostgreSQL server has no folder
  // of this node's, so it needs one.
  std::filesystem::path spool;
  std::string ae_title = "MAXILLO";
  uint16_t port = 11112;
  std::vector<AllowedPeer> allowed;  // calling AE titles (and addresses) that may associate; empty: none
  int max_associations = 8;
  int timeout_seconds = 30;  // association negotiation and each DIMSE message
  // When a study has had nothing new archived for stable_seconds, this shell command runs once
  // (again after each later change), with MAXILLO_ARCHIVE, MAXILLO_STUDY_UID and MAXILLO_CASE (the
  // archive id of the patient's default case) in its environment. Empty: no action.
  std::string on_stable_study;
  int stable_seconds = 60;
  // Run in the server for each stable study's case (the patient's default case), before the
  // command: `maxillo serve` checks the CT's header against the anatomy here (issue 28), so a
  // contradiction is recorded and said when the study has arrived, as at import. Its errors
  // (a study with no volume: a report, a single slice) are logged at debug level and go no
  // further. Set, it turns the stable-study watch on without a command.
  std::function<void(Archive& archive, int64_t case_id)> check_stable_case;
  // DICOM TLS (net/tls_options.h): on when there is a certificate; callers must then present a
  // certificate signed by a trusted one when `trusted` is not empty.
  TlsOptions tls;
};

// What the server did since it started.
struct StorageServerCounts {
  int64_t associations = 0;      // accepted
  int64_t refused = 0;           // associations refused (unknown calling AE or address, wrong called AE)
  int64_t stored = 0;            // instances archived anew
  int64_t already_archived = 0;  // identical instances received again
  int64_t failed = 0;            // C-STOREs answered with a failure status
  int64_t stable_actions = 0;    // stable-study commands run
  int64_t failed_actions = 0;    // ... of which exited non-zero
};

class StorageServer {
 public:
  // Checks the options (AE titles, port, limits: Error(kUsage); TLS files: net/tls_layer.h) and
  // opens or creates the archive.
  explicit StorageServer(StorageServerOptions options);
  ~StorageServer();
  StorageServer(const StorageServer&) = delete;
  StorageServer& operator=(const StorageServer&) = delete;

  // Listens on 0.0.0.0:port until stop(). Error(kWriteFailed) when the port cannot be opened,
  // before `on_listening` is called (so "listening" is never said of a port taken by another).
  void run(const std::function<void()>& on_listening = {});
  // Stops accepting associations; run() returns once those in flight have ended. Any thread.
  void stop();
  StorageServerCounts counts() const;

  struct Shared;  // what every association's thread reads and counts into (storage_server.cpp)

 private:
  std::unique_ptr<Shared> shared_;
};

}  // namespace maxillo::net
