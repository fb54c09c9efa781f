// maxillo echo AE@HOST:PORT: C-ECHO a DICOM peer (is it there, does it accept our AE title).
#include <iostream>

#include "archive/archive_json.h"
#include "cli/command.h"
#include "cli/network_options.h"
#include "net/echo_client.h"

namespace maxillo::cli {
namespace {

struct EchoArguments {
  std::string peer;
  net::EchoOptions options;
};

void run_echo(const EchoArguments& a, CommandContext& ctx) {
  const net::DicomPeer peer = net::parse_peer(a.peer);
  const double seconds = net::echo(peer, a.options);
  if (ctx.global.json)
    std::cout << json_text(Json{{"peer", net::to_string(peer)}, {"seconds", seconds}}) << "\n";
  else
    std::cout << net::to_string(peer) << " answered in " << seconds << " s\n";
}

}  // namespace

void attach_echo(CLI::App& app, CommandContext& ctx) {
  auto a = std::make_shared<EchoArguments>();
  app.add_option("PEER", a->peer, "AE@HOST:PORT, e.g. PACS@127.0.0.1:4242")->required();
  add_requestor_options(app, a->options.calling_ae, a->options.timeout_seconds, a->options.tls);
  app.callback([a, &ctx] { run_echo(*a, ctx); });
}

}  // namespace maxillo::cli
