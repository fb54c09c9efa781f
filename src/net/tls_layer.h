#pragma once
// Internal to src/net: DCMTK's TLS transport layer from TlsOptions (net/tls_options.h), with the
// BCP 195 non-downgrading profile (TLS 1.2 or later, forward-secret ciphers), as DCMTK's own tools
// offer it. The layer must outlive every association that uses it.
#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmtls/tlslayer.h>

#include <memory>

#include "net/tls_options.h"

namespace maxillo::net {

// For `maxillo serve`; nullptr when TLS is off. Error(kUsage) when a certificate has no key or
// the reverse; Error(kFileNotFound / kBadValue) naming the file that is missing or unusable, or
// the key that does not match its certificate.
std::unique_ptr<DcmTLSTransportLayer> acceptor_tls(const TlsOptions& options);

// For the requestors (echo, send, find, retrieve); nullptr when TLS is off. As above, and
// Error(kUsage) when no trusted certificate is given: a client always verifies the server.
std::unique_ptr<DcmTLSTransportLayer> requestor_tls(const TlsOptions& options);

}  // namespace maxillo::net
