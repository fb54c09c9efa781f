#pragma once
// DICOM TLS (the Secure Transport Connection Profile, PS3.15 B.1) as a user configures it: our
// certificate and private key, and the certificates we trust for the peer. Plain paths here;
// net/tls_layer.h turns them into DCMTK's transport layer.
//
// A server (maxillo serve) uses TLS when it has a certificate. With trusted certificates it also
// requires every caller to present a certificate signed by one of them (mutual authentication);
// without, callers are not authenticated by certificate (the AE title list still applies).
// A client (echo, send, find, retrieve) uses TLS when asked to, and always verifies the peer's
// certificate against its trusted ones; its own certificate is optional (for servers that ask).
#include <filesystem>
#include <vector>

namespace maxillo::net {

struct TlsOptions {
  bool enabled = false;
  std::filesystem::path certificate{};  // ours, PEM
  std::filesystem::path private_key{};  // its key, PEM, not encrypted
  // PEM certificate files, or folders of certificates named by their subject hash (c_rehash)
  std::vector<std::filesystem::path> trusted{};
};

}  // namespace maxillo::net
