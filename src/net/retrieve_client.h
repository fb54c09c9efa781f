#pragma once
// Retrieving a study from a PACS into the archive, by C-GET (default) or C-MOVE.
//
// C-GET: the peer sends the instances back on our own association; no port to open, nothing to
// configure at the peer beyond letting us retrieve. C-MOVE, for the PACS that only offer it: the
// peer opens associations of its own to the destination it has configured for our AE title, so
// we listen on `move_port` for the duration (net/move_destination.h), accepting only the peer.
// Either way the instances are written bit for bit into a scratch folder and then archived by
// the import, exactly as `maxillo import` would archive the same files. A progress bar follows
// the peer's pending responses (completed and remaining sub-operations).
#include <cstddef>
#include <cstdint>
#include <string>

#include "archive/archive.h"
#include "net/dicom_peer.h"
#include "net/tls_options.h"

namespace maxillo::net {

struct RetrieveOptions {
  std::string calling_ae = "MAXILLO";
  int timeout_seconds = 60;
  TlsOptions tls;
  uint16_t move_port = 0;  // 0: C-GET; otherwise C-MOVE to calling_ae, received on this port
  ProgressDisplay progress = ProgressDisplay::Auto;
};

// A retrieve's DIMSE status as a person reads it: "0xC000 (Failed: UnableToProcess)" (service:
// "C-GET" or "C-MOVE", whose statuses DCMTK names).
std::string status_text(const std::string& service, uint16_t status);

struct RetrieveReport {
  size_t received = 0;        // instances the peer sent
  size_t failed_by_peer = 0;  // sub-operations the peer reported failed
  size_t sent_by_peer = 0;    // sub-operations the peer reported completed (instances it says it sent)
  ImportReport imported;      // what the archive made of the received instances
  double seconds = 0;
};

// Error(kNetwork) naming the peer when the association fails, the peer offers no C-GET (C-MOVE)
// or answers it with a failure; Error(kWriteFailed) when the C-MOVE port cannot be opened.
RetrieveReport retrieve_study(const DicomPeer& peer, const std::string& study_uid, Archive& archive,
                              const RetrieveOptions& options = {});

}  // namespace maxillo::net
