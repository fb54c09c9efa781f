// maxillo serve --aet AET --port PORT --allow AE[@HOST]...: a DICOM storage server that archives
// what scanners and PACS push (net/storage_server.h). Runs until SIGTERM or SIGINT, then lets the
// associations in flight finish and prints what it did.
#include <signal.h>
#include <unistd.h>

#include <cerrno>

#include <iostream>
#include <map>
#include <thread>

#include "archive/archive_json.h"
#include "cli/command.h"
#include "core/error.h"
#include "core/log.h"
#include "net/serve_config.h"
#include "casework/landmarks/case_orientation.h"
#include "net/storage_server.h"

namespace maxillo::cli {
namespace {

struct ServeArguments {
  std::filesystem::path config;
  std::string ae_title = "MAXILLO";
  int port = 11112;
  std::vector<std::string> allowed;
  int max_associations = 8;
  int timeout_seconds = 30;
  std::string on_stable_study;
  int stable_seconds = 60;
  std::filesystem::path spool;
  net::TlsOptions tls;
  // The options given on the command line (they override the configuration file).
  std::map<std::string, CLI::Option*> given;
  bool on_command_line(const std::string& name) const { return given.at(name)->count() > 0; }
};

// SIGTERM and SIGINT ask the server to stop. Libraries start threads of their own before main
// (OpenBLAS), so blocking the signals cannot cover every thread: a handler takes the signal in
// whichever thread it lands and only writes a byte into a pipe (async-signal-safe); a thread
// reading the pipe does the rest.
int stop_pipe[2] = {-1, -1};

extern "C" void on_stop_signal(int) {
  const char byte = 's';
  [[maybe_unused]] const auto written = write(stop_pipe[1], &byte, 1);
}

class StopOnSignal {
 public:
  explicit StopOnSignal(net::StorageServer& server) {
    if (pipe(stop_pipe) != 0) throw Error(ErrorCode::kProcessing, "serve", "cannot create the stop pipe");
    struct sigaction action {};
    action.sa_handler = on_stop_signal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGTERM, &action, nullptr);
    sigaction(SIGINT, &action, nullptr);
    waiter_ = std::thread([&server] {
      char byte = 0;
      while (read(stop_pipe[0], &byte, 1) < 0 && errno == EINTR) {}
      if (byte == 's') log::info("serve: stop requested: finishing the associations in flight");
      server.stop();
    });
  }
  ~StopOnSignal() {
    const char byte = 'x';  // wakes the waiter when no signal came
    [[maybe_unused]] const auto written = write(stop_pipe[1], &byte, 1);
    waiter_.join();
    signal(SIGTERM, SIG_DFL);
    signal(SIGINT, SIG_DFL);
    close(stop_pipe[0]);
    close(stop_pipe[1]);
  }

 private:
  std::thread waiter_;
};

// The options: the configuration file's (net/serve_config.h), then those given on the command line.
net::StorageServerOptions server_options(const ServeArguments& a, const GlobalOptions& global) {
  net::StorageServerOptions options = a.config.empty() ? net::StorageServerOptions{} : net::read_serve_config(a.config);
  options.archive = resolve_archive_dir(global);
  if (a.config.empty() || a.on_command_line("--aet")) options.ae_title = a.ae_title;
  if (a.config.empty() || a.on_command_line("--port")) options.port = uint16_t(a.port);
  if (a.on_command_line("--allow"))
    for (const auto& text : a.allowed) options.allowed.push_back(net::parse_allowed_peer(text));
  if (a.config.empty() || a.on_command_line("--max-associations")) options.max_associations = a.max_associations;
  if (a.config.empty() || a.on_command_line("--timeout")) options.timeout_seconds = a.timeout_seconds;
  if (a.config.empty() || a.on_command_line("--on-stable-study")) options.on_stable_study = a.on_stable_study;
  if (a.config.empty() || a.on_command_line("--stable-seconds")) options.stable_seconds = a.stable_seconds;
  if (a.on_command_line("--spool")) options.spool = a.spool;
  // Each study, once it has arrived, has its case's CT header checked against the anatomy, as
  // `maxillo import` does (casework/landmarks/case_orientation.h): a contradiction is recorded and logged.
  options.check_stable_case = [](Archive& archive, int64_t case_id) { casework::case_orientation(archive, case_id); };
  if (a.on_command_line("--tls-cert")) {
    options.tls = {.enabled = true, .certificate = a.tls.certificate, .private_key = a.tls.private_key, .trusted = {}};
    if (!a.on_command_line("--tls-key")) throw Error(ErrorCode::kUsage, "--tls-cert", "needs --tls-key");
  }
  if (a.on_command_line("--tls-trust"))
    options.tls.trusted.insert(options.tls.trusted.end(), a.tls.trusted.begin(), a.tls.trusted.end());
  return options;
}

void run_serve(const ServeArguments& a, CommandContext& ctx) {
  const net::StorageServerOptions options = server_options(a, ctx.global);
  if (options.allowed.empty()) log::warning("serve: no --allow given: every association will be refused");
  net::StorageServer server(options);
  {
    StopOnSignal stop_on_signal(server);
    server.run([&] {
      if (!ctx.global.quiet)
        std::cerr << "serve: " << options.ae_title << " listening on port " << options.port
                  << (options.tls.enabled ? " (DICOM TLS)" : "") << "\n";
    });
  }
  const auto counts = server.counts();
  if (ctx.global.json) {
    std::cout << json_text(Json{{"associations", counts.associations},
                                {"refused_associations", counts.refused},
                                {"stored", counts.stored},
                                {"already_archived", counts.already_archived},
                                {"failed", counts.failed},
                                {"stable_study_actions", counts.stable_actions},
                                {"failed_stable_study_actions", counts.failed_actions}})
              << "\n";
  } else {
    std::cout << "serve stopped: " << counts.associations << " associations (" << counts.refused << " refused), "
              << counts.stored << " instances archived, " << counts.already_archived << " already archived, "
              << counts.failed << " refused; " << counts.stable_actions << " stable-study actions ("
              << counts.failed_actions << " failed)\n";
  }
}

}  // namespace

void attach_serve(CLI::App& app, CommandContext& ctx) {
  auto a = std::make_shared<ServeArguments>();
  auto& given = a->given;
  app.add_option("--config", a->config,
                 "JSON configuration (README: Receiving from scanners and PACS); options given here override it")
      ->check(CLI::ExistingFile);
  given["--aet"] = app.add_option("--aet", a->ae_title, "our AE title (peers call it)")->capture_default_str();
  given["--port"] =
      app.add_option("--port", a->port, "TCP port to listen on")->check(CLI::Range(1, 65535))->capture_default_str();
  given["--allow"] = app.add_option("--allow", a->allowed,
                                    "a peer that may store: AE title, or AE@ADDRESS (repeatable; others are refused)");
  given["--max-associations"] = app.add_option("--max-associations", a->max_associations,
                                               "associations served at once (more are refused as busy)")
                                    ->check(CLI::Range(1, 64))
                                    ->capture_default_str();
  given["--timeout"] =
      app.add_option("--timeout", a->timeout_seconds, "seconds a peer may stay silent before it is dropped")
          ->check(CLI::Range(1, 3600))
          ->capture_default_str();
  given["--on-stable-study"] = app.add_option(
      "--on-stable-study", a->on_stable_study,
      "shell command run once a study has had nothing new for --stable-seconds (again after each change); "
      "environment: MAXILLO_ARCHIVE, MAXILLO_STUDY_UID, MAXILLO_CASE");
  given["--stable-seconds"] =
      app.add_option(
             "--stable-seconds", a->stable_seconds,
             "quiet time after which a study is stable: its case's CT header is then checked against the anatomy "
             "(as at import), and --on-stable-study run")
          ->check(CLI::Range(1, 86400))
          ->capture_default_str();
  given["--spool"] = app.add_option("--spool", a->spool,
                                    "this node's folder for files being received and owed actions (default: the "
                                    "archive folder; required with an archive on a PostgreSQL server)");
  given["--tls-cert"] = app.add_option("--tls-cert", a->tls.certificate, "our certificate (PEM): serve DICOM TLS only")
                            ->check(CLI::ExistingFile);
  given["--tls-key"] =
      app.add_option("--tls-key", a->tls.private_key, "the certificate's private key (PEM)")->check(CLI::ExistingFile);
  given["--tls-trust"] = app.add_option("--tls-trust", a->tls.trusted,
                                        "a certificate file or folder: callers must present a certificate signed by "
                                        "one of them (repeatable; adds to the configuration's)")
                             ->check(CLI::ExistingPath);
  app.callback([a, &ctx] { run_serve(*a, ctx); });
}

}  // namespace maxillo::cli
