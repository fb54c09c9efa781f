#pragma once
// The listening loop of `maxillo serve`: accepts DICOM associations on a port and serves each in
// a thread of its own, up to a limit, until asked to stop; then waits for those in flight.
//
// DCMTK's DcmBaseSCPPool does the same, and `serve` used it until 2026-12-05. In DCMTK 3.6.7 (the
// version Debian 12 ships) a worker that ends before pthread_create has returned in the listening
// thread is deleted by its own exit, and OFThread::start then writes the new thread's id into the
// freed worker: a refused association ends within microseconds, so on a loaded machine the heap
// was corrupted and the server aborted ("malloc(): unsorted double linked list corrupted",
// valgrind: an invalid write in OFThread::start from DcmBaseSCPPool::runAssociation). DCMTK
// reworked its pool's thread handling in 2025 (reused workers), after 3.6.7. Here each
// association's thread is a std::thread owned by the loop and joined by it, so nothing it uses is
// freed before it has ended.
//
// A connection that fails before it is an association (a failed TLS handshake, a client that does
// not speak DICOM) is passed to `on_receive_failure` with DCMTK's reason; a quiet period is none.
#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/assoc.h>
#include <dcmtk/dcmnet/scpcfg.h>

#include <atomic>
#include <functional>
#include <memory>
#include <string>

namespace maxillo::net {

class AssociationPool {
 public:
  // Runs in the association's own thread and answers it to its end (DcmThreadSCP::run, which
  // drops and destroys the association).
  using Serve = std::function<void(T_ASC_Association* association, const DcmSharedSCPConfig& config)>;
  using ReceiveFailure = std::function<void(const std::string& reason)>;

  // `config`: the port, the ACSE and connection timeouts, the blocking mode, the largest PDU and
  // the transport layer (TLS) are read from it; it must outlive listen().
  AssociationPool(const DcmSCPConfig& config, int max_associations, Serve serve, ReceiveFailure on_receive_failure);
  ~AssociationPool();
  AssociationPool(const AssociationPool&) = delete;
  AssociationPool& operator=(const AssociationPool&) = delete;

  // Accepts associations until `stop` is set (looked at after every connection timeout or
  // association), then waits for those in flight. A caller beyond max_associations is rejected
  // (local limit exceeded). Returns DCMTK's condition when the network cannot be opened.
  OFCondition listen(const std::atomic<bool>& stop);

 private:
  struct Running;
  void start(T_ASC_Association* association, const DcmSharedSCPConfig& shared);
  void join_finished();
  void join_all();

  const DcmSCPConfig& config_;
  int max_associations_;
  Serve serve_;
  ReceiveFailure on_receive_failure_;
  std::unique_ptr<Running> running_;
};

}  // namespace maxillo::net
