#include "net/tls_layer.h"

#include <mutex>

#include "core/error.h"

namespace maxillo::net {
namespace {

void require_file(const std::filesystem::path& file, const std::string& what) {
  if (!std::filesystem::exists(file)) throw Error(ErrorCode::kFileNotFound, file.string(), "no such " + what);
}

void load_identity(DcmTLSTransportLayer& layer, const TlsOptions& options) {
  if (options.certificate.empty() != options.private_key.empty())
    throw Error(ErrorCode::kUsage, "--tls-cert/--tls-key", "a TLS certificate needs its private key, and the reverse");
  if (options.certificate.empty()) return;
  require_file(options.certificate, "TLS certificate");
  require_file(options.private_key, "TLS private key");
  if (layer.setPrivateKeyFile(options.private_key.c_str(), DCF_Filetype_PEM).bad())
    throw Error(ErrorCode::kBadValue, options.private_key.string(), "not a readable, unencrypted PEM private key");
  if (layer.setCertificateFile(options.certificate.c_str(), DCF_Filetype_PEM).bad())
    throw Error(ErrorCode::kBadValue, options.certificate.string(), "not a readable PEM certificate");
  if (!layer.checkPrivateKeyMatchesCertificate())
    throw Error(ErrorCode::kBadValue, options.private_key.string(),
                "this private key does not belong to the certificate " + options.certificate.string());
}

void load_trusted(DcmTLSTransportLayer& layer, const TlsOptions& options) {
  for (const auto& trusted : options.trusted) {
    require_file(trusted, "trusted certificate file or folder");
    const OFCondition loaded = std::filesystem::is_directory(trusted)
                                   ? layer.addTrustedCertificateDir(trusted.c_str(), DCF_Filetype_PEM)
                                   : layer.addTrustedCertificateFile(trusted.c_str(), DCF_Filetype_PEM);
    if (loaded.bad()) throw Error(ErrorCode::kBadValue, trusted.string(), "not a readable PEM certificate (or folder)");
  }
}

std::unique_ptr<DcmTLSTransportLayer> make_layer(T_ASC_NetworkRole role, const TlsOptions& options) {
  // OpenSSL's library set-up, once per process, before the first layer.
  static std::once_flag openssl_ready;
  std::call_once(openssl_ready, [] { DcmTLSTransportLayer::initializeOpenSSL(); });
  auto layer = std::make_unique<DcmTLSTransportLayer>(role, nullptr, OFFalse);
  load_identity(*layer, options);
  load_trusted(*layer, options);
  if (OFCondition c = layer->setTLSProfile(TSP_Profile_BCP195_ND); c.bad())
    throw Error(ErrorCode::kProcessing, "TLS", std::string("cannot set the BCP 195 profile: ") + c.text());
  if (OFCondition c = layer->activateCipherSuites(); c.bad())
    throw Error(ErrorCode::kProcessing, "TLS", std::string("cannot activate the cipher suites: ") + c.text());
  return layer;
}

}  // namespace

std::unique_ptr<DcmTLSTransportLayer> acceptor_tls(const TlsOptions& options) {
  if (!options.enabled) return nullptr;
  if (options.certificate.empty())
    throw Error(ErrorCode::kUsage, "--tls-cert", "a TLS server needs its certificate and private key");
  auto layer = make_layer(NET_ACCEPTOR, options);
  layer->setCertificateVerification(options.trusted.empty() ? DCV_ignoreCertificate : DCV_requireCertificate);
  return layer;
}

std::unique_ptr<DcmTLSTransportLayer> requestor_tls(const TlsOptions& options) {
  if (!options.enabled) return nullptr;
  if (options.trusted.empty())
    throw Error(ErrorCode::kUsage, "--tls-trust",
                "TLS needs the certificate (or its CA) that the peer's must be signed by");
  auto layer = make_layer(NET_REQUESTOR, options);
  layer->setCertificateVerification(DCV_requireCertificate);
  return layer;
}

}  // namespace maxillo::net
