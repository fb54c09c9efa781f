// Issue 15: DICOM TLS. `maxillo serve` with a certificate and a trusted CA, against DCMTK's own
// echoscu/storescu and against `maxillo send` and `maxillo echo`: a caller with a certificate the
// CA signed stores over TLS; a plain TCP caller, a caller whose certificate the CA did not sign,
// and a client that does not trust the server's certificate are all refused, and nothing reaches
// the archive from them. Certificates are made for the test by the openssl tool.
#include <gtest/gtest.h>

#include "archive/archive.h"
#include "support/run_command.h"
#include "support/run_maxillo.h"
#include "support/temporary_folder.h"
#include "net_fixture.h"

namespace maxillo {
namespace {

using testing::quote;
using testing::run_command;

// A CA, a server and a client certificate it signs, and a stranger's self-signed certificate.
class TestCertificates {
 public:
  explicit TestCertificates(const std::filesystem::path& folder) : folder_(folder) {
    std::filesystem::create_directories(folder_);
    authority("ca");
    signed_by_ca("server");
    signed_by_ca("client");
    authority("stranger");
  }
  std::filesystem::path pem(const std::string& name) const { return folder_ / (name + ".pem"); }
  std::filesystem::path key(const std::string& name) const { return folder_ / (name + ".key"); }

 private:
  void openssl(const std::string& arguments) const {
    const auto result = run_command("cd " + quote(folder_) + " && openssl " + arguments + " 2>&1");
    ASSERT_EQ(result.exit_code, 0) << "openssl " << arguments << ": " << result.output;
  }
  void authority(const std::string& name) const {
    openssl("req -x509 -newkey rsa:2048 -nodes -sha256 -days 2 -subj /CN=" + name + " -keyout " + name + ".key -out " +
            name + ".pem");
  }
  void signed_by_ca(const std::string& name) const {
    openssl("req -newkey rsa:2048 -nodes -sha256 -subj /CN=" + name + " -keyout " + name + ".key -out " + name +
            ".csr");
    openssl("x509 -req -sha256 -days 2 -in " + name + ".csr -CA ca.pem -CAkey ca.key -CAcreateserial -out " + name +
            ".pem");
  }
  std::filesystem::path folder_;
};

class ServeTls : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!testing::tool_available("echoscu") || !testing::tool_available("storescu") ||
        !testing::tool_available("openssl"))
      GTEST_SKIP() << "DCMTK's echoscu/storescu or openssl are not installed (scripts/setup installs them)";
    certificates_.emplace(folder_ / "certificates");
    if (HasFatalFailure()) return;
    port_ = testing::free_loopback_port();
    server_ = testing::start_maxillo(
        {"--archive", archive().string(), "serve", "--port", std::to_string(port_), "--allow", "STORESCU", "--allow",
         "ECHOSCU", "--allow", "MAXILLO", "--timeout", "10", "--tls-cert", cert("server").string(), "--tls-key",
         key("server").string(), "--tls-trust", cert("ca").string()},
        folder_ / "serve.out", folder_ / "serve.err");
    ASSERT_GT(server_, 0);
    for (int attempt = 0; attempt < 200 && echo_with("client").exit_code != 0; ++attempt)
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    ASSERT_EQ(echo_with("client").exit_code, 0) << testing::slurp(folder_ / "serve.err");
  }
  void TearDown() override {
    if (server_ > 0) testing::stop_process(server_);
  }

  std::filesystem::path cert(const std::string& name) const { return certificates_->pem(name); }
  std::filesystem::path key(const std::string& name) const { return certificates_->key(name); }
  std::filesystem::path archive() const { return folder_ / "archive"; }
  std::string address() const { return "127.0.0.1 " + std::to_string(port_); }

  // echoscu over TLS with `identity`'s certificate, trusting our CA.
  testing::CommandResult echo_with(const std::string& identity) const {
    return run_command("echoscu -aet ECHOSCU -aec MAXILLO +tls " + quote(key(identity)) + " " + quote(cert(identity)) +
                       " +cf " + quote(cert("ca")) + " " + address() + " 2>&1");
  }
  // storescu with `tls` options (empty: plain TCP).
  testing::CommandResult store(const std::string& tls, const std::vector<std::filesystem::path>& files) const {
    std::string line = "storescu -aet STORESCU -aec MAXILLO " + tls + " " + address();
    for (const auto& file : files) line += " " + quote(file);
    return run_command(line + " 2>&1");
  }
  size_t archived_instances() const {
    Archive opened = Archive::open(archive());
    size_t count = 0;
    for (const auto& series : opened.series()) count += opened.instances(series.id).size();
    return count;
  }

  TemporaryFolder folder_{"serve-tls"};
  std::optional<TestCertificates> certificates_;
  uint16_t port_ = 0;
  pid_t server_ = -1;
};

TEST_F(ServeTls, ArchivesFromACallerTheCaSignedAndRefusesEveryOtherCaller) {
  const auto series = testing::write_series(folder_ / "series", "TLS1", 5, 0);
  const std::string signed_client =
      "+tls " + quote(key("client")) + " " + quote(cert("client")) + " +cf " + quote(cert("ca"));
  const std::string stranger =
      "+tls " + quote(key("stranger")) + " " + quote(cert("stranger")) + " +cf " + quote(cert("ca"));
  const auto plain = store("", {series.files[0]});
  EXPECT_NE(plain.exit_code, 0) << plain.output;
  const auto unknown = store(stranger, {series.files[0]});
  EXPECT_NE(unknown.exit_code, 0) << unknown.output;
  const auto anonymous = store("+tla +cf " + quote(cert("ca")), {series.files[0]});
  EXPECT_NE(anonymous.exit_code, 0) << anonymous.output;
  EXPECT_EQ(archived_instances(), 0u);

  const auto good = store(signed_client, series.files);
  EXPECT_EQ(good.exit_code, 0) << good.output;
  EXPECT_EQ(archived_instances(), 5u);
  EXPECT_EQ(testing::stop_process(server_), 0);
  server_ = -1;
  EXPECT_NE(testing::slurp(folder_ / "serve.out").find("5 instances archived"), std::string::npos);
  // The three failed handshakes are logged and counted as refusals (issue 29, fault 12).
  EXPECT_NE(testing::slurp(folder_ / "serve.out").find("(3 refused)"), std::string::npos)
      << testing::slurp(folder_ / "serve.out");
  EXPECT_NE(testing::slurp(folder_ / "serve.err").find("a connection failed before its association"), std::string::npos)
      << testing::slurp(folder_ / "serve.err");
}

TEST_F(ServeTls, MaxilloSendsAndEchoesOverTlsAndVerifiesTheServer) {
  const auto series = testing::write_series(folder_ / "series", "TLS2", 4, 100);
  const std::string peer = "MAXILLO@127.0.0.1:" + std::to_string(port_);
  const std::vector<std::string> identity = {"--tls-cert", cert("client").string(), "--tls-key",
                                             key("client").string()};
  auto with = [](std::vector<std::string> command, const std::vector<std::string>& more) {
    command.insert(command.end(), more.begin(), more.end());
    return command;
  };
  const auto source = folder_ / "source";
  Archive::open(source, OpenMode::CreateIfMissing)
      .import_paths({folder_ / "series"}, {.progress = ProgressDisplay::Never});
  const std::vector<std::string> send = {"--archive", source.string(), "send", series.series_instance_uid, "--to",
                                         peer};
  const auto sent =
      testing::run_maxillo(with(with(send, identity), {"--tls-trust", cert("ca").string()}), folder_.path());
  EXPECT_EQ(sent.exit_code, 0) << sent.err;
  EXPECT_EQ(archived_instances(), 4u);

  const auto echoed =
      testing::run_maxillo(with({"echo", peer, "--tls-trust", cert("ca").string()}, identity), folder_.path());
  EXPECT_EQ(echoed.exit_code, 0) << echoed.err;
  // A server whose certificate the stranger CA did not sign is not trusted.
  const auto untrusted =
      testing::run_maxillo(with({"echo", peer, "--tls-trust", cert("stranger").string()}, identity), folder_.path());
  EXPECT_EQ(untrusted.exit_code, exit_code_for(ErrorCode::kNetwork)) << untrusted.err;
  // TLS without anything to verify the server by is a usage error, before any connection.
  const auto unverified = testing::run_maxillo({"echo", peer, "--tls"}, folder_.path());
  EXPECT_EQ(unverified.exit_code, exit_code_for(ErrorCode::kUsage));
  EXPECT_NE(unverified.err.find("--tls-trust"), std::string::npos) << unverified.err;
}

TEST(ServeTlsSetUp, AKeyThatIsNotTheCertificatesIsRefusedByName) {
  if (!testing::tool_available("openssl")) GTEST_SKIP() << "openssl is not installed";
  TemporaryFolder folder("serve-tls-key");
  const TestCertificates certificates(folder / "certificates");
  const auto result =
      testing::run_maxillo({"--archive", (folder / "archive").string(), "serve", "--port", "4", "--tls-cert",
                            certificates.pem("server").string(), "--tls-key", certificates.key("client").string()},
                           folder.path());
  EXPECT_EQ(result.exit_code, exit_code_for(ErrorCode::kBadValue)) << result.err;
  EXPECT_NE(result.err.find("does not belong to the certificate"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("client.key"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace maxillo
