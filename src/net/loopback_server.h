#pragma once
// A storage server of ours on a free loopback port for the duration of one piece of work: the
// demo's simulated scanner and PACS, and anyone who wants to push files through the network path
// inside one process. The server runs on its own thread; `work` gets the peer to call.
#include <functional>

#include "net/storage_server.h"

namespace maxillo::net {

// options.port is replaced by a free loopback port. Returns the server's counts once `work` has
// returned and the server has stopped; an exception from `work` or from the server (its port)
// is rethrown after the server has stopped.
StorageServerCounts with_loopback_server(StorageServerOptions options,
                                         const std::function<void(const DicomPeer&)>& work);

}  // namespace maxillo::net
