#include "net/move_destination.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/dstorscp.h>

#include "core/error.h"
#include "core/log.h"
#include "net/storage_contexts.h"
#include "net/tls_layer.h"

namespace maxillo::net {

// DCMTK's storage SCP, told whom to accept and when to stop.
struct MoveDestination::Listener : public DcmStorageSCP {
  Listener(std::string peer, std::atomic<bool>& stop) : peer_ae_title(std::move(peer)), stop_requested(stop) {}

  OFBool checkCallingAETitleAccepted(const OFString& calling_ae) override {
    if (calling_ae == peer_ae_title.c_str()) return OFTrue;
    log::warning("retrieve: an association from '", calling_ae.c_str(),
                 "' to our C-MOVE destination was refused: only ", peer_ae_title, " may deliver");
    return OFFalse;
  }
  // Checked between associations (the accept loop wakes every second).
  OFBool stopAfterConnectionTimeout() override { return stop_requested.load(); }

  std::string peer_ae_title;
  std::atomic<bool>& stop_requested;
  std::unique_ptr<DcmTLSTransportLayer> tls;
};

MoveDestination::MoveDestination(const std::filesystem::path& folder, const std::string& ae_title, uint16_t port,
                                 const std::string& peer_ae_title, int timeout_seconds, const TlsOptions& tls)
    : listener_(std::make_unique<Listener>(peer_ae_title, stop_)) {
  Listener& scp = *listener_;
  scp.setOutputDirectory(folder.c_str());
  scp.setDatasetStorageMode(DcmStorageSCP::DGM_StoreBitPreserving);
  scp.setFilenameGenerationMode(DcmStorageSCP::FGM_UniqueFromNewUID);
  DcmSCPConfig& config = scp.getConfig();
  config.setAETitle(ae_title.c_str());
  config.setPort(port);
  config.setRespondWithCalledAETitle(OFFalse);
  config.setHostLookupEnabled(OFFalse);
  config.setConnectionBlockingMode(DUL_NOBLOCK);
  config.setConnectionTimeout(1);
  config.setDIMSEBlockingMode(DIMSE_NONBLOCKING);
  config.setDIMSETimeout(Uint32(timeout_seconds));
  config.setACSETimeout(Uint32(timeout_seconds));
  accept_storage(config);
  if (tls.enabled) {
    scp.tls = acceptor_tls(tls);
    config.setTransportLayer(scp.tls.get());
  }
  if (OFCondition opened = scp.openListenPort(); opened.bad())
    throw Error(ErrorCode::kWriteFailed, "port " + std::to_string(port),
                std::string("cannot receive the C-MOVE here: ") + opened.text());
  accepting_ = std::thread([&scp] { scp.acceptAssociations(); });
}

MoveDestination::~MoveDestination() {
  stop_ = true;
  accepting_.join();
}

}  // namespace maxillo::net
