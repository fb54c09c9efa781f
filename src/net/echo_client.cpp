#include "net/echo_client.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmnet/scu.h>

#include <chrono>

#include "core/error.h"
#include "net/no_nagle_delay.h"

namespace maxillo::net {

double echo(const DicomPeer& peer, const EchoOptions& options) {
  check_ae_title(options.calling_ae, "--aet");
  const auto started = std::chrono::steady_clock::now();
  auto fail = [&](const std::string& what, const OFCondition& condition) -> double {
    throw Error(ErrorCode::kNetwork, to_string(peer), what + ": " + condition.text());
  };
  no_nagle_delay();
  DcmSCU scu;
  scu.setAETitle(options.calling_ae.c_str());
  scu.setPeerAETitle(peer.ae_title.c_str());
  scu.setPeerHostName(peer.host.c_str());
  scu.setPeerPort(peer.port);
  scu.setConnectionTimeout(options.timeout_seconds);
  scu.setACSETimeout(Uint32(options.timeout_seconds));
  scu.setDIMSEBlockingMode(DIMSE_NONBLOCKING);
  scu.setDIMSETimeout(Uint32(options.timeout_seconds));
  OFList<OFString> syntaxes;
  syntaxes.push_back(UID_LittleEndianImplicitTransferSyntax);
  scu.addPresentationContext(UID_VerificationSOPClass, syntaxes);
  if (OFCondition c = scu.initNetwork(); c.bad()) fail("cannot set up the network", c);
  if (OFCondition c = scu.negotiateAssociation(); c.bad()) fail("association failed", c);
  const OFCondition echoed = scu.sendECHORequest(0);
  scu.releaseAssociation();
  if (echoed.bad()) fail("C-ECHO failed", echoed);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

}  // namespace maxillo::net
