#include "net/echo_client.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcuid.h>

#include <chrono>

#include "core/error.h"
#include "net/association_requestor.h"
#include "net/tls_layer.h"

namespace maxillo::net {

double echo(const DicomPeer& peer, const EchoOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const auto tls = requestor_tls(options.tls);  // outlives the association
  Requestor scu;
  configure_requestor(scu, peer, options.calling_ae, options.timeout_seconds, tls.get());
  OFList<OFString> syntaxes;
  syntaxes.push_back(UID_LittleEndianImplicitTransferSyntax);
  scu.addPresentationContext(UID_VerificationSOPClass, syntaxes);
  request_association(scu, peer);
  const OFCondition echoed = scu.sendECHORequest(0);
  scu.releaseAssociation();
  if (echoed.bad()) throw Error(ErrorCode::kNetwork, to_string(peer), std::string("C-ECHO failed: ") + echoed.text());
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

}  // namespace maxillo::net
