#pragma once
// C-STORE SCU: sends DICOM files to a peer on one association, each in the transfer syntax it is
// stored in (no re-encoding: the peer receives the archived bytes' data set). Every file gets its
// own answer; a refused file is reported and the rest are sent.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "core/progress.h"
#include "net/dicom_peer.h"
#include "net/tls_options.h"

namespace maxillo::net {

struct StoreOptions {
  std::string calling_ae = "MAXILLO";
  int timeout_seconds = 30;
  TlsOptions tls;
  ProgressDisplay progress = ProgressDisplay::Auto;
};

struct StoreFailure {
  std::filesystem::path file;
  std::string reason;  // the peer's status (and its Error Comment when given), or why it was not sent
};

struct StoreReport {
  size_t sent = 0;  // answered with success (or a warning status)
  std::vector<StoreFailure> failures;
  double seconds = 0;
};

// Error(kNetwork) naming the peer when no association can be made at all (unreachable, rejected,
// or none of the files' SOP classes and transfer syntaxes accepted); Error(kNotDicom) naming the
// file when a file has no readable meta header (checked before connecting).
StoreReport send_files(const DicomPeer& peer, const std::vector<std::filesystem::path>& files,
                       const StoreOptions& options = {});

}  // namespace maxillo::net
