#pragma once
// The options every command that calls a DICOM peer shares (echo, send, find, retrieve).
#include <CLI/CLI.hpp>

#include <string>

#include "net/tls_options.h"

namespace maxillo::cli {

// DICOM TLS for a requestor (net/tls_options.h): any of these turns it on; the peer's certificate
// is always verified, so --tls needs --tls-trust.
inline void add_requestor_tls_options(CLI::App& app, net::TlsOptions& tls) {
  const auto turn_on = [&tls](const auto&) { tls.enabled = true; };
  app.add_flag("--tls", tls.enabled, "DICOM TLS (needs --tls-trust)");
  app.add_option("--tls-trust", tls.trusted,
                 "a certificate file, or a folder of them, that the peer's must be signed by")
      ->check(CLI::ExistingPath)
      ->each(turn_on);
  app.add_option("--tls-cert", tls.certificate, "our certificate (PEM), for peers that require one")
      ->check(CLI::ExistingFile)
      ->each(turn_on);
  app.add_option("--tls-key", tls.private_key, "our certificate's private key (PEM)")->check(CLI::ExistingFile);
}

inline void add_requestor_options(CLI::App& app, std::string& calling_ae, int& timeout_seconds, net::TlsOptions& tls) {
  app.add_option("--aet", calling_ae, "our (calling) AE title")->capture_default_str();
  app.add_option("--timeout", timeout_seconds, "seconds for connecting and for each answer")
      ->check(CLI::Range(1, 3600))
      ->capture_default_str();
  add_requestor_tls_options(app, tls);
}

}  // namespace maxillo::cli
