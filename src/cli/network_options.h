#pragma once
// The options every command that calls a DICOM peer shares (echo, send, find, retrieve).
#include <CLI/CLI.hpp>

#include <string>

namespace maxillo::cli {

inline void add_requestor_options(CLI::App& app, std::string& calling_ae, int& timeout_seconds) {
  app.add_option("--aet", calling_ae, "our (calling) AE title")->capture_default_str();
  app.add_option("--timeout", timeout_seconds, "seconds for connecting and for each answer")
      ->check(CLI::Range(1, 3600))
      ->capture_default_str();
}

}  // namespace maxillo::cli
