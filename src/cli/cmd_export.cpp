// maxillo export SERIES --out DIR: the original files of a series, byte-identical.
#include <iostream>

#include "archive/archive.h"
#include "cli/command.h"
#include "core/json.h"

namespace maxillo::cli {

void attach_export(CLI::App& app, CommandContext& ctx) {
  struct Arguments {
    std::string series;
    std::filesystem::path out;
  };
  auto args = std::make_shared<Arguments>();
  app.add_option("SERIES", args->series, "series archive id or Series Instance UID")->required();
  app.add_option("--out", args->out, "folder to write the files into (created)")->required();
  app.callback([args, &ctx] {
    Archive archive = Archive::open(resolve_archive_dir(ctx.global));
    auto files = archive.export_series(archive.resolve_series(args->series), args->out);
    if (ctx.global.json) {
      Json list = Json::array();
      for (const auto& f : files) list.push_back(f.string());
      std::cout << Json{{"series", args->series}, {"files", list}}.dump(2) << "\n";
    } else {
      std::cout << files.size() << " files written to " << args->out.string() << "\n";
    }
  });
}

}  // namespace maxillo::cli
