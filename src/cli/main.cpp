// maxillo: the command-line entry point. Parses global options, dispatches to the command
// table and turns errors into the exit codes of core/error_catalogue.def.
#include <cmath>
#include <cstdlib>
#include <iostream>

#include "cli/command.h"
#include "core/error.h"
#include "core/log.h"

namespace maxillo::cli {

std::filesystem::path resolve_archive_dir(const GlobalOptions& global) {
  if (!global.archive_dir.empty()) return global.archive_dir;
  if (const char* env = std::getenv("MAXILLO_ARCHIVE"); env && *env) return env;
  return "maxillo-archive";
}

namespace {

void configure_logging(const GlobalOptions& global) {
  if (global.quiet)
    log::set_level(log::Level::Error);
  else if (global.verbosity > 0)
    log::set_level(log::Level::Debug);
}

// CLI11 reads "nan", "inf" and "1e400" as doubles; no numeric option of maxillo means them.
// Every floating-point option of every command gets this check (ranges are each option's own).
void refuse_non_finite_numbers(CLI::App& app) {
  static const CLI::Validator finite(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (end != text.c_str() && *end == '\0' && !std::isfinite(value)) return "must be a finite number, got " + text;
        return {};
      },
      "", "");
  for (CLI::Option* option : app.get_options())
    if (option->get_type_name().find("FLOAT") != std::string::npos) option->check(finite);
  for (CLI::App* subcommand : app.get_subcommands([](CLI::App*) { return true; }))
    refuse_non_finite_numbers(*subcommand);
}

// An empty value names no file, folder, series or patient: `--out ''` ended in an internal error
// (issue 29). Every option that takes a value refuses an empty one, as a usage error.
void refuse_empty_values(CLI::App& app) {
  static const CLI::Validator non_empty([](std::string& text) { return text.empty() ? "must not be empty" : ""; }, "",
                                        "");
  for (CLI::Option* option : app.get_options())
    if (option->get_type_size_min() > 0) option->check(non_empty);
  for (CLI::App* subcommand : app.get_subcommands([](CLI::App*) { return true; })) refuse_empty_values(*subcommand);
}

int run(int argc, char** argv) {
  CLI::App app{"maxillo: cranio-maxillofacial planning, simulation and reports", "maxillo"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "help for every command");
  CommandContext context;
  app.add_option("--archive", context.global.archive_dir,
                 "archive folder, or a PostgreSQL index with its shared object folder: "
                 "postgresql://USER@HOST:PORT/DATABASE?objects=/shared/folder "
                 "(default: $MAXILLO_ARCHIVE or ./maxillo-archive)");
  app.add_flag("--json", context.global.json, "machine-readable output on stdout");
  app.add_flag("-v,--verbose", context.global.verbosity, "debug logging (may show patient identifiers)");
  app.add_flag("-q,--quiet", context.global.quiet, "errors only");
  app.parse_complete_callback([&] { configure_logging(context.global); });

  for (const auto& command : command_table()) {
    CLI::App* sub = app.add_subcommand(std::string(command.name), std::string(command.summary));
    sub->group(std::string(command.group));
    sub->fallthrough();  // global options may follow the command name
    command.attach(*sub, context);
  }
  refuse_non_finite_numbers(app);
  refuse_empty_values(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? 0 : exit_code_for(ErrorCode::kUsage);
  }
  return context.exit_code;
}

}  // namespace
}  // namespace maxillo::cli

int main(int argc, char** argv) {
  try {
    return maxillo::cli::run(argc, argv);
  } catch (const maxillo::Error& e) {
    maxillo::log::error(e.what());
    return maxillo::exit_code_for(e.code());
  } catch (const std::exception& e) {
    maxillo::log::error("internal error: ", e.what());
    return maxillo::exit_code_for(maxillo::ErrorCode::kProcessing);
  }
}
