// maxillo show ID: one patient, study, series, instance or case, found by archive id,
// Patient ID or UID, with what it contains.
#include <iostream>

#include "archive/archive.h"
#include "archive/archive_json.h"
#include "cli/command.h"
#include "records/orientation_record.h"

namespace maxillo::cli {
namespace {

Json describe_item(const Archive& archive, const ResolvedItem& item) {
  switch (item.kind) {
    case ItemKind::Patient: {
      Json json = to_json(archive.patient(item.id).value());
      Json studies = Json::array();
      for (const auto& s : archive.studies(item.id)) studies.push_back(to_json(s));
      json["studies_list"] = studies;
      if (auto c = archive.case_of_patient(item.id)) json["default_case"] = c->id;
      return json;
    }
    case ItemKind::Study: {
      Json json = to_json(archive.study(item.id).value());
      Json series = Json::array();
      for (const auto& s : archive.series(item.id)) series.push_back(to_json(s));
      json["series_list"] = series;
      return json;
    }
    case ItemKind::Series: {
      Json json = to_json(archive.series_by_id(item.id).value());
      Json instances = Json::array();
      for (const auto& i : archive.instances(item.id)) instances.push_back(to_json(i));
      json["instances_list"] = instances;
      return json;
    }
    case ItemKind::Instance:
      if (auto instance = archive.instance(item.id)) return to_json(*instance);
      return Json::object();
    case ItemKind::Case: {
      Json json = to_json(archive.case_contents(item.id));
      json["artefacts"] = Json::array();
      for (const auto& a : archive.artefacts(item.id)) json["artefacts"].push_back(to_json(a));
      const auto orientation = records::latest_orientations(archive, {item.id});
      if (!orientation.empty()) json["orientation"] = records::to_json(orientation.begin()->second);
      return json;
    }
  }
  return Json::object();
}

// Text form: the scalar fields as "key: value", lists as indented one-line summaries.
void print_text(const Json& json, int indent = 0) {
  std::string pad(indent, ' ');
  for (const auto& [key, value] : json.items()) {
    if (value.is_array() && !value.empty() && value.front().is_object()) {
      std::cout << pad << key << ": " << value.size() << "\n";
      for (const auto& entry : value) {
        std::cout << pad << "  -";
        for (const auto& [k, v] : entry.items())
          if (!v.is_structured() && (k == "id" || k.find("uid") != std::string::npos || k == "description" ||
                                     k == "role" || k == "instance_number" || k == "modality" || k == "date"))
            std::cout << " " << k << "=" << (v.is_string() ? v.get<std::string>() : json_text(v, -1));
        std::cout << "\n";
      }
    } else if (value.is_object()) {
      std::cout << pad << key << ":\n";
      print_text(value, indent + 2);
    } else {
      std::cout << pad << key << ": " << (value.is_string() ? value.get<std::string>() : json_text(value, -1)) << "\n";
    }
  }
}

}  // namespace

void attach_show(CLI::App& app, CommandContext& ctx) {
  auto id = std::make_shared<std::string>();
  app.add_option("ID", *id,
                 "archive id (typed: patient:N, study:N, series:N, instance:N, case:N), Patient ID, or "
                 "Study/Series/SOP Instance UID")
      ->required();
  app.callback([id, &ctx] {
    Archive archive = Archive::open(resolve_archive_dir(ctx.global));
    ResolvedItem item = archive.resolve(*id);
    Json json = describe_item(archive, item);
    if (ctx.global.json) {
      std::cout << json_text(Json{{"kind", to_string(item.kind)}, {"id", item.id}, {"item", json}}) << "\n";
    } else {
      std::cout << to_string(item.kind) << " " << item.id << "\n";
      print_text(json, 2);
    }
  });
}

}  // namespace maxillo::cli
