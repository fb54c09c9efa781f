#include "net/loopback_server.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "core/error.h"
#include "net/echo_client.h"

namespace maxillo::net {
namespace {

// A port nothing listens on now: the kernel's choice for an ephemeral bind on loopback.
uint16_t free_loopback_port() {
  const int s = socket(AF_INET, SOCK_STREAM, 0);
  if (s < 0) throw Error(ErrorCode::kNetwork, "127.0.0.1", "cannot open a socket");
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t length = sizeof address;
  const bool bound = bind(s, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
                     getsockname(s, reinterpret_cast<sockaddr*>(&address), &length) == 0;
  close(s);
  if (!bound) throw Error(ErrorCode::kNetwork, "127.0.0.1", "no free loopback port");
  return ntohs(address.sin_port);
}

// Until the server answers C-ECHO (it listens within a few milliseconds of starting).
void wait_until_answering(const DicomPeer& peer, const std::string& calling_ae, const std::atomic<bool>& server_ended) {
  for (int attempt = 0; attempt < 100 && !server_ended; ++attempt) {
    try {
      echo(peer, {.calling_ae = calling_ae, .timeout_seconds = 2, .tls = {}});
      return;
    } catch (const Error&) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }
  throw Error(ErrorCode::kNetwork, to_string(peer), "the loopback server did not come up");
}

}  // namespace

StorageServerCounts with_loopback_server(StorageServerOptions options,
                                         const std::function<void(const DicomPeer&)>& work) {
  options.port = free_loopback_port();
  const DicomPeer peer{options.ae_title, "127.0.0.1", options.port};
  const std::string caller = options.allowed.empty() ? options.ae_title : options.allowed.front().ae_title;
  StorageServer server(std::move(options));
  std::exception_ptr server_failed, work_failed;  // each written by one thread, read after the join
  std::atomic<bool> server_ended{false};
  std::thread serving([&] {
    try {
      server.run();
    } catch (...) {
      server_failed = std::current_exception();
    }
    server_ended = true;
  });
  try {
    wait_until_answering(peer, caller, server_ended);
    work(peer);
  } catch (...) {
    work_failed = std::current_exception();
  }
  server.stop();
  serving.join();
  if (server_failed) std::rethrow_exception(server_failed);
  if (work_failed) std::rethrow_exception(work_failed);
  return server.counts();
}

}  // namespace maxillo::net
