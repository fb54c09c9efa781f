// The serve configuration file: every key read, and a typo or a bad value named with its key.
#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "core/temporary_folder.h"
#include "net/serve_config.h"

namespace maxillo::net {
namespace {

std::string error_reading(const std::filesystem::path& file) {
  try {
    read_serve_config(file);
  } catch (const Error& error) {
    return error.reason();
  }
  return "no error";
}

TEST(ServeConfig, ReadsEveryKey) {
  TemporaryFolder folder("serve-config");
  std::ofstream(folder / "serve.json") << R"({"ae_title": "CLINIC", "port": 4242, "allow": ["CBCT", "PACS@10.0.0.5"],
      "max_associations": 3, "timeout_seconds": 12, "stable_study": {"after_seconds": 90, "command": "true"}})";
  const auto options = read_serve_config(folder / "serve.json");
  EXPECT_EQ(options.ae_title, "CLINIC");
  EXPECT_EQ(options.port, 4242);
  ASSERT_EQ(options.allowed.size(), 2u);
  EXPECT_EQ(options.allowed[1].ae_title, "PACS");
  EXPECT_EQ(options.allowed[1].host, "10.0.0.5");
  EXPECT_EQ(options.max_associations, 3);
  EXPECT_EQ(options.timeout_seconds, 12);
  EXPECT_EQ(options.stable_seconds, 90);
  EXPECT_EQ(options.on_stable_study, "true");
}

TEST(ServeConfig, ReadsTlsPathsFromTheConfigurationsFolder) {
  TemporaryFolder folder("serve-config");
  std::filesystem::create_directories(folder / "etc");
  std::ofstream(folder / "etc" / "serve.json")
      << R"({"tls": {"certificate": "server.pem", "private_key": "/keys/server.key", "trusted": ["ca.pem", "peers"]}})";
  const auto options = read_serve_config(folder / "etc" / "serve.json");
  EXPECT_TRUE(options.tls.enabled);
  EXPECT_EQ(options.tls.certificate, folder / "etc" / "server.pem");
  EXPECT_EQ(options.tls.private_key, "/keys/server.key");
  ASSERT_EQ(options.tls.trusted.size(), 2u);
  EXPECT_EQ(options.tls.trusted[1], folder / "etc" / "peers");
}

TEST(ServeConfig, NamesTheKeyOfATypoOrABadValue) {
  TemporaryFolder folder("serve-config");
  const std::pair<const char*, const char*> cases[] = {
      {R"({"prot": 4242})", "prot: unknown key"},
      {R"({"port": 70000})", "port: expected a whole number from 1 to 65535"},
      {R"({"port": "4242"})", "port: expected a whole number"},
      {R"({"allow": ["OK", "TOO_LONG_AE_TITLE_X"]})", "allow[1]: an AE title has 1 to 16 characters"},
      {R"({"stable_study": {"after": 5}})", "stable_study.after: unknown key"},
      {R"({"ae_title": ""})", "ae_title: an AE title has 1 to 16 characters"},
      {R"({"tls": {"certificate": "server.pem"}})", "tls: a TLS server needs \"certificate\" and \"private_key\""},
      {R"({"tls": {"certificate": "a", "private_key": "b", "trusted": "ca.pem"}})", "tls.trusted: expected a list"},
      {R"({"tls": {"cert": "a"}})", "tls.cert: unknown key"},
  };
  for (const auto& [text, expected] : cases) {
    std::ofstream(folder / "serve.json") << text;
    EXPECT_NE(error_reading(folder / "serve.json").find(expected), std::string::npos)
        << text << " gave: " << error_reading(folder / "serve.json");
  }
}

}  // namespace
}  // namespace maxillo::net
