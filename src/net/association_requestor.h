#pragma once
// Internal to src/net: what every request we send needs, on DCMTK's DcmSCU. The caller proposes
// its presentation contexts between configure_requestor and request_association.
#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/scu.h>

#include <string>

#include "net/dicom_peer.h"

namespace maxillo::net {

// DcmSCU that can speak TLS with a layer from net/tls_layer.h. DCMTK's own DcmTLSSCU would do it
// with certificate options of its own; the layer can only be attached once the network exists.
class Requestor : public DcmSCU {
 public:
  void use_tls(DcmTransportLayer* layer) { tls_ = layer; }
  OFCondition initNetwork() override {
    OFCondition ready = DcmSCU::initNetwork();
    if (ready.good() && tls_ != nullptr) ready = useSecureConnection(tls_);
    return ready;
  }

 private:
  DcmTransportLayer* tls_ = nullptr;  // not owned
};

// Our AE title, the peer, timeouts for connecting, negotiating and every answer (non-blocking
// DIMSE, so a silent peer cannot hold us), no Nagle delay (no_nagle_delay.h), and TLS when `tls`
// is not null (net/tls_layer.h: it must outlive the association).
void configure_requestor(Requestor& scu, const DicomPeer& peer, const std::string& calling_ae, int timeout_seconds,
                         DcmTransportLayer* tls);

// Connects and negotiates. Error(kNetwork) naming the peer: unreachable, or rejected and why.
void request_association(DcmSCU& scu, const DicomPeer& peer);

// The accepted presentation context for `abstract_syntax`; when there is none the association is
// released and Error(kNetwork) says the peer does not offer `service`.
T_ASC_PresentationContextID require_context(DcmSCU& scu, const DicomPeer& peer, const char* abstract_syntax,
                                            const std::string& service);

}  // namespace maxillo::net
