#pragma once
// The CLI is a table of subcommands (commands.cpp). Each command lives in its own file
// cmd_<name>.cpp with one function that declares its options on a CLI11 subcommand and
// installs a callback. Callbacks parse nothing themselves: options are bound to typed
// variables once, unknown values are rejected by CLI11 validators, and the work is done
// by library calls. A callback returns the process exit code through ctx.exit_code.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace maxillo::cli {

struct GlobalOptions {
  std::filesystem::path archive_dir;  // --archive, else $MAXILLO_ARCHIVE, else ./maxillo-archive
  bool json = false;                  // --json: machine-readable output on stdout
  int verbosity = 0;                  // -v: debug logging (may include patient identifiers)
  bool quiet = false;                 // -q: errors only
};

struct CommandContext {
  GlobalOptions global;
  int exit_code = 0;
};

using AttachCommand = void (*)(CLI::App& subcommand, CommandContext& context);

struct CommandSpec {
  std::string_view name;
  std::string_view group;    // heading under which --help lists the command
  std::string_view summary;  // one line for --help
  AttachCommand attach;
};

// Every command, in the order --help shows them.
std::span<const CommandSpec> command_table();

// Ranges shared by several commands' options.
inline const CLI::Range kCoordinateMm(-1.0e4, 1.0e4);  // a position in the patient or model frame
inline const CLI::Range kAdvancementMm(-60.0, 60.0);   // a bone move, as plan create limits it
inline const CLI::Range kTetrahedra(5000, 2000000);    // a face model: fewer cannot resolve a face
inline const CLI::Range kCellMm(1.0, 20.0);            // target tetrahedron size of a face model
inline const CLI::Range kTriangles(1000, 5000000);     // a surface's decimation target

// The archive folder the global options and environment select.
std::filesystem::path resolve_archive_dir(const GlobalOptions& global);

}  // namespace maxillo::cli
