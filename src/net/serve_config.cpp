#include "net/serve_config.h"

#include <fstream>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/json_input.h"

namespace maxillo::net {
namespace {

class ConfigReader {
 public:
  ConfigReader(const Json& json, const std::filesystem::path& file)
      : json_(json), source_(file.string()), folder_(file.parent_path()) {}

  [[noreturn]] void fail(const std::string& key, const std::string& reason) const {
    throw Error(ErrorCode::kBadValue, source_, key + ": " + reason);
  }

  void only_keys(const Json& object, const std::set<std::string>& known, const std::string& prefix) const {
    if (!object.is_object()) fail(prefix.empty() ? "(top level)" : prefix, "expected an object");
    for (const auto& [key, value] : object.items())
      if (!known.count(key)) fail(prefix + key, "unknown key");
  }

  int integer(const Json& object, const std::string& key, const std::string& path, int low, int high,
              int fallback) const {
    if (!object.contains(key)) return fallback;
    const Json& value = object.at(key);
    if (!value.is_number_integer() || value.get<int64_t>() < low || value.get<int64_t>() > high)
      fail(path, "expected a whole number from " + std::to_string(low) + " to " + std::to_string(high));
    return value.get<int>();
  }

  std::string text(const Json& object, const std::string& key, const std::string& path, std::string fallback) const {
    if (!object.contains(key)) return fallback;
    if (!object.at(key).is_string()) fail(path, "expected a string");
    return object.at(key).get<std::string>();
  }

  StorageServerOptions read() const {
    only_keys(json_, {"ae_title", "port", "allow", "max_associations", "timeout_seconds", "stable_study", "tls"}, "");
    StorageServerOptions options;
    options.ae_title = text(json_, "ae_title", "ae_title", options.ae_title);
    check_or_fail([&] { check_ae_title(options.ae_title, "ae_title"); }, "ae_title");
    options.port = uint16_t(integer(json_, "port", "port", 1, 65535, options.port));
    options.max_associations = integer(json_, "max_associations", "max_associations", 1, 64, options.max_associations);
    options.timeout_seconds = integer(json_, "timeout_seconds", "timeout_seconds", 1, 3600, options.timeout_seconds);
    if (json_.contains("allow")) {
      const Json& allow = json_.at("allow");
      if (!allow.is_array()) fail("allow", "expected a list of \"AE\" or \"AE@ADDRESS\"");
      for (size_t i = 0; i < allow.size(); ++i) {
        const std::string path = "allow[" + std::to_string(i) + "]";
        if (!allow[i].is_string()) fail(path, "expected \"AE\" or \"AE@ADDRESS\"");
        check_or_fail([&] { options.allowed.push_back(parse_allowed_peer(allow[i].get<std::string>())); }, path);
      }
    }
    if (json_.contains("stable_study")) {
      const Json& stable = json_.at("stable_study");
      only_keys(stable, {"after_seconds", "command"}, "stable_study.");
      options.stable_seconds =
          integer(stable, "after_seconds", "stable_study.after_seconds", 1, 86400, options.stable_seconds);
      options.on_stable_study = text(stable, "command", "stable_study.command", "");
    }
    if (json_.contains("tls")) options.tls = tls(json_.at("tls"));
    return options;
  }

 private:
  // Runs a check that throws a usage Error and re-throws it as a bad value of this file and key.
  void check_or_fail(auto check, const std::string& path) const {
    try {
      check();
    } catch (const Error& error) {
      fail(path, error.reason());
    }
  }

  std::filesystem::path file_path(const Json& object, const std::string& key, const std::string& path) const {
    const std::string value = text(object, key, path, "");
    if (value.empty()) return {};
    return folder_ / value;  // an absolute value stays as it is
  }

  TlsOptions tls(const Json& object) const {
    only_keys(object, {"certificate", "private_key", "trusted"}, "tls.");
    TlsOptions options{.enabled = true,
                       .certificate = file_path(object, "certificate", "tls.certificate"),
                       .private_key = file_path(object, "private_key", "tls.private_key")};
    if (options.certificate.empty() || options.private_key.empty())
      fail("tls", "a TLS server needs \"certificate\" and \"private_key\"");
    if (object.contains("trusted")) {
      const Json& trusted = object.at("trusted");
      if (!trusted.is_array()) fail("tls.trusted", "expected a list of certificate files or folders");
      for (size_t i = 0; i < trusted.size(); ++i) {
        const std::string path = "tls.trusted[" + std::to_string(i) + "]";
        if (!trusted[i].is_string() || trusted[i].get<std::string>().empty()) fail(path, "expected a file or folder");
        options.trusted.push_back(folder_ / trusted[i].get<std::string>());
      }
    }
    return options;
  }

  const Json& json_;
  std::string source_;
  std::filesystem::path folder_;  // relative paths are read from here
};

}  // namespace

StorageServerOptions read_serve_config(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(ErrorCode::kFileNotFound, file.string(), "cannot read the configuration file");
  std::ostringstream text;
  text << in.rdbuf();
  const Json json = parse_json_input(text.str(), file.string());
  return ConfigReader(json, file).read();
}

}  // namespace maxillo::net
