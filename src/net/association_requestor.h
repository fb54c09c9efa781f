#pragma once
// Internal to src/net: what every request we send needs, on DCMTK's DcmSCU. The caller proposes
// its presentation contexts between configure_requestor and request_association.
#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/scu.h>

#include <string>

#include "net/dicom_peer.h"

namespace maxillo::net {

// Our AE title, the peer, timeouts for connecting, negotiating and every answer (non-blocking
// DIMSE, so a silent peer cannot hold us), and no Nagle delay (no_nagle_delay.h).
void configure_requestor(DcmSCU& scu, const DicomPeer& peer, const std::string& calling_ae, int timeout_seconds);

// Connects and negotiates. Error(kNetwork) naming the peer: unreachable, or rejected and why.
void request_association(DcmSCU& scu, const DicomPeer& peer);

// The accepted presentation context for `abstract_syntax`; when there is none the association is
// released and Error(kNetwork) says the peer does not offer `service`.
T_ASC_PresentationContextID require_context(DcmSCU& scu, const DicomPeer& peer, const char* abstract_syntax,
                                            const std::string& service);

}  // namespace maxillo::net
