#pragma once
// C-ECHO (the DICOM "ping"): is a peer there, does it accept our AE title, does it answer?
#include <string>

#include "net/dicom_peer.h"
#include "net/tls_options.h"

namespace maxillo::net {

struct EchoOptions {
  std::string calling_ae = "MAXILLO";
  int timeout_seconds = 10;  // connecting, negotiating and waiting for the answer, each
  TlsOptions tls;
};

// Returns the round trip in seconds (association, echo, release). Error(kNetwork) naming the peer
// and what failed: no connection, association rejected (and why), or a non-success status.
double echo(const DicomPeer& peer, const EchoOptions& options = {});

}  // namespace maxillo::net
