#pragma once
// Retrieving a study from a PACS with C-GET: the peer sends the instances back on our own
// association (no listening port, no AE title to configure at the peer beyond allowing us to
// retrieve), written bit for bit into a scratch folder and then archived by the import, exactly
// as `maxillo import` would archive the same files.
#include <cstddef>
#include <string>

#include "archive/archive.h"
#include "net/dicom_peer.h"
#include "net/tls_options.h"

namespace maxillo::net {

struct RetrieveOptions {
  std::string calling_ae = "MAXILLO";
  int timeout_seconds = 60;
  TlsOptions tls;
  ProgressDisplay progress = ProgressDisplay::Auto;
};

struct RetrieveReport {
  size_t received = 0;         // instances the peer sent
  size_t failed_by_peer = 0;   // sub-operations the peer reported failed
  ImportReport imported;       // what the archive made of the received instances
  double seconds = 0;
};

// Error(kNetwork) naming the peer when the association fails, the peer offers no C-GET or
// answers the C-GET with a failure.
RetrieveReport retrieve_study(const DicomPeer& peer, const std::string& study_uid, Archive& archive,
                              const RetrieveOptions& options = {});

}  // namespace maxillo::net
