#pragma once
// DCMTK 3.6.7 leaves Nagle's algorithm on unless the environment variable TCP_NODELAY is set
// (dcmnet/libsrc/dulfsm.cc). A C-STORE's small command and response messages then wait for the
// peer's delayed acknowledgement: storescu to storescp on loopback took 89 ms per instance, 1.7 ms
// with TCP_NODELAY=1 on both ends. Orthanc sets TCP_NODELAY on its sockets too.
#include <cstdlib>

namespace maxillo::net {

// Sets TCP_NODELAY=1 for the DCMTK connections this process opens or accepts from now on, unless
// the user set the variable (TCP_NODELAY=0 keeps Nagle's algorithm).
inline void no_nagle_delay() { setenv("TCP_NODELAY", "1", 0); }

}  // namespace maxillo::net
