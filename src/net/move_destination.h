#pragma once
// Internal to src/net: where a C-MOVE delivers. The PACS that answers a C-MOVE opens associations
// of its own to the destination AE title it has configured (our AE title, this machine, a port)
// and sends the instances there as C-STOREs. This is a storage SCP for the duration of one
// retrieve: it listens on `port` as `ae_title`, accepts only the PACS's AE title, and writes each
// instance bit for bit (no re-encoding) into a scratch folder for the import.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>

#include "net/tls_options.h"

namespace maxillo::net {

class MoveDestination {
 public:
  // Opens the port (Error(kWriteFailed) naming it when that fails) and starts accepting.
  MoveDestination(const std::filesystem::path& folder, const std::string& ae_title, uint16_t port,
                  const std::string& peer_ae_title, int timeout_seconds, const TlsOptions& tls);
  // Waits for the association in flight, if any, then stops listening.
  ~MoveDestination();
  MoveDestination(const MoveDestination&) = delete;
  MoveDestination& operator=(const MoveDestination&) = delete;

  struct Listener;  // move_destination.cpp

 private:
  std::atomic<bool> stop_{false};
  std::unique_ptr<Listener> listener_;
  std::thread accepting_;
};

}  // namespace maxillo::net
