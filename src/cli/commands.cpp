#include <array>

#include "cli/command.h"

namespace maxillo::cli {

// One declaration per cmd_<name>.cpp.
void attach_version(CLI::App&, CommandContext&);

std::span<const CommandSpec> command_table() {
  static const std::array kCommands = {
      CommandSpec{"version", "General", "print the program version", attach_version},
  };
  return kCommands;
}

}  // namespace maxillo::cli
