// maxillo export SERIES --out DIR [--deidentify]: a series' files, byte-identical as archived,
// or de-identified for research and teaching (pseudonyms keyed by the archive's secret).
#include <iostream>

#include "archive/archive.h"
#include "cli/command.h"
#include "core/json.h"

namespace maxillo::cli {

void attach_export(CLI::App& app, CommandContext& ctx) {
  struct Arguments {
    std::string series;
    std::filesystem::path out;
    bool deidentify = false;
  };
  auto args = std::make_shared<Arguments>();
  app.add_option("SERIES", args->series, "series archive id or Series Instance UID")->required();
  app.add_option("--out", args->out, "folder to write the files into (created)")->required();
  app.add_flag("--deidentify", args->deidentify,
               "remove identifying attributes (DICOM PS3.15 basic profile, dates retained), pseudonymous "
               "Patient ID and name, new UIDs; the same archive gives the same pseudonyms");
  app.callback([args, &ctx] {
    Archive archive = Archive::open(resolve_archive_dir(ctx.global));
    auto profile = args->deidentify ? ExportProfile::Deidentified : ExportProfile::Original;
    auto files = archive.export_series(archive.resolve_series(args->series), args->out, profile);
    if (ctx.global.json) {
      Json list = Json::array();
      for (const auto& f : files) list.push_back(f.string());
      std::cout << json_text(Json{{"series", args->series}, {"deidentified", args->deidentify}, {"files", list}})
                << "\n";
    } else {
      std::cout << files.size() << (args->deidentify ? " de-identified" : "") << " files written to "
                << args->out.string() << "\n";
    }
  });
}

}  // namespace maxillo::cli
