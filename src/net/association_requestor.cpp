#include "net/association_requestor.h"

#include "core/error.h"
#include "dicom/dicom_header.h"
#include "net/no_nagle_delay.h"

namespace maxillo::net {

void configure_requestor(Requestor& scu, const DicomPeer& peer, const std::string& calling_ae, int timeout_seconds,
                         DcmTransportLayer* tls) {
  check_ae_title(calling_ae, "--aet");
  initialise_dicom_toolkit();  // DCMTK's own log lines off, as everywhere in maxillo
  no_nagle_delay();
  scu.setAETitle(calling_ae.c_str());
  scu.setPeerAETitle(peer.ae_title.c_str());
  scu.setPeerHostName(peer.host.c_str());
  scu.setPeerPort(peer.port);
  scu.setConnectionTimeout(timeout_seconds);
  scu.setACSETimeout(Uint32(timeout_seconds));
  scu.setDIMSEBlockingMode(DIMSE_NONBLOCKING);
  scu.setDIMSETimeout(Uint32(timeout_seconds));
  scu.use_tls(tls);
}

void request_association(DcmSCU& scu, const DicomPeer& peer) {
  if (OFCondition c = scu.initNetwork(); c.bad())
    throw Error(ErrorCode::kNetwork, to_string(peer), std::string("cannot set up the network: ") + c.text());
  if (OFCondition c = scu.negotiateAssociation(); c.bad())
    throw Error(ErrorCode::kNetwork, to_string(peer), std::string("association failed: ") + c.text());
}

T_ASC_PresentationContextID require_context(DcmSCU& scu, const DicomPeer& peer, const char* abstract_syntax,
                                            const std::string& service) {
  const T_ASC_PresentationContextID context = scu.findPresentationContextID(abstract_syntax, "");
  if (context != 0) return context;
  scu.releaseAssociation();
  throw Error(ErrorCode::kNetwork, to_string(peer), "the peer does not offer " + service);
}

}  // namespace maxillo::net
