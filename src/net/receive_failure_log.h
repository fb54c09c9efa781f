#pragma once
// Connections that fail before they become an association (a failed TLS handshake, a client
// that is not DICOM): DCMTK's pool reports them only to its own log, which maxillo silences, so
// `serve` said nothing of them and did not count them as refusals (issue 29). While an object of
// this class lives, those reports of DCMTK's network logger are passed to `on_failure`.
#include <functional>
#include <string>

namespace maxillo::net {

class ReceiveFailureLog {
 public:
  explicit ReceiveFailureLog(std::function<void(const std::string& reason)> on_failure);
  ~ReceiveFailureLog();
  ReceiveFailureLog(const ReceiveFailureLog&) = delete;
  ReceiveFailureLog& operator=(const ReceiveFailureLog&) = delete;

 private:
  struct Hook;
  Hook* hook_;
};

}  // namespace maxillo::net
