#include "net/association_pool.h"

#include <dcmtk/dcmnet/dul.h>

#include <list>
#include <thread>

#include "core/log.h"

namespace maxillo::net {

// The associations being served: each thread sets its flag as its last act, and the listening
// loop joins the threads whose flag is set before it accepts the next caller.
struct AssociationPool::Running {
  struct Association {
    std::thread thread;
    std::shared_ptr<std::atomic<bool>> ended = std::make_shared<std::atomic<bool>>(false);
  };
  std::list<Association> associations;
};

namespace {

void drop_and_destroy(T_ASC_Association* association) {
  ASC_dropAssociation(association);
  ASC_destroyAssociation(&association);
}

// As DcmBaseSCPPool answers a caller it has no thread for.
void reject_as_busy(T_ASC_Association* association) {
  T_ASC_RejectParameters rejection;
  rejection.result = ASC_RESULT_REJECTEDTRANSIENT;
  rejection.source = ASC_SOURCE_SERVICEPROVIDER_PRESENTATION_RELATED;
  rejection.reason = ASC_REASON_SP_PRES_LOCALLIMITEXCEEDED;
  ASC_rejectAssociation(association, &rejection);
  drop_and_destroy(association);
}

}  // namespace

AssociationPool::AssociationPool(const DcmSCPConfig& config, int max_associations, Serve serve,
                                 ReceiveFailure on_receive_failure)
    : config_(config),
      max_associations_(max_associations),
      serve_(std::move(serve)),
      on_receive_failure_(std::move(on_receive_failure)),
      running_(std::make_unique<Running>()) {}

AssociationPool::~AssociationPool() { join_all(); }

OFCondition AssociationPool::listen(const std::atomic<bool>& stop) {
  T_ASC_Network* network = nullptr;
  OFCondition opened =
      ASC_initializeNetwork(NET_ACCEPTOR, int(config_.getPort()), int(config_.getACSETimeout()), &network);
  if (opened.good() && config_.transportLayerEnabled()) {
    opened = ASC_setTransportLayer(network, config_.getTransportLayer(), 0 /* not handed over */);
    if (opened.bad()) ASC_dropNetwork(&network);
  }
  if (opened.bad()) return opened;

  const DcmSharedSCPConfig shared(config_);  // what every association's thread reads
  while (!stop) {
    T_ASC_Association* association = nullptr;
    const OFCondition received = ASC_receiveAssociation(
        network, &association, long(config_.getMaxReceivePDULength()), nullptr, nullptr,
        config_.transportLayerEnabled(), config_.getConnectionBlockingMode(), int(config_.getConnectionTimeout()));
    join_finished();
    if (received.good()) {
      if (int(running_->associations.size()) >= max_associations_)
        reject_as_busy(association);
      else
        start(association, shared);
    } else if (received == DUL_NOASSOCIATIONREQUEST) {
      ASC_destroyAssociation(&association);  // a quiet connection timeout: look at `stop` again
    } else {
      drop_and_destroy(association);
      if (on_receive_failure_) on_receive_failure_(received.text());
    }
  }
  join_all();
  ASC_dropNetwork(&network);
  return EC_Normal;
}

void AssociationPool::start(T_ASC_Association* association, const DcmSharedSCPConfig& shared) {
  Running::Association& running = running_->associations.emplace_back();
  running.thread = std::thread([this, association, &shared, ended = running.ended] {
    try {
      serve_(association, shared);
    } catch (const std::exception& error) {
      log::warning("serve: an association ended with an error: ", error.what());
    }
    *ended = true;
  });
}

void AssociationPool::join_finished() {
  auto& associations = running_->associations;
  for (auto it = associations.begin(); it != associations.end();) {
    if (!*it->ended) {
      ++it;
      continue;
    }
    it->thread.join();
    it = associations.erase(it);
  }
}

void AssociationPool::join_all() {
  for (auto& running : running_->associations) running.thread.join();
  running_->associations.clear();
}

}  // namespace maxillo::net
