#include <iostream>

#include "cli/command.h"
#include "core/json.h"
#include "core/version.h"

namespace maxillo::cli {

void attach_version(CLI::App& app, CommandContext& ctx) {
  app.callback([&ctx] {
    if (ctx.global.json)
      std::cout << nlohmann::json{{"version", kVersion}}.dump() << "\n";
    else
      std::cout << "maxillo " << kVersion << "\n";
  });
}

}  // namespace maxillo::cli
