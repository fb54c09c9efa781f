// maxillo list [patients|studies|series|cases|flags]: what the archive holds.
#include <cstdio>
#include <iostream>

#include "archive/archive.h"
#include "archive/archive_json.h"
#include "cli/command.h"
#include "records/orientation_record.h"

namespace maxillo::cli {
namespace {

std::string millimetres(const std::optional<double>& value) {
  if (!value) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", *value);
  return text;
}

template <typename Records>
void print_json(const Records& records) {
  Json list = Json::array();
  for (const auto& record : records) list.push_back(to_json(record));
  std::cout << json_text(list) << "\n";
}

long long ll(int64_t value) { return static_cast<long long>(value); }

void list_patients(const Archive& archive, bool json) {
  auto rows = archive.patients();
  if (json) return print_json(rows);
  std::printf("%-5s %-20s %-32s %-9s %-3s %s\n", "id", "patient id", "name", "birth", "sex", "studies");
  for (const auto& r : rows)
    std::printf("%-5lld %-20s %-32s %-9s %-3s %lld\n", ll(r.id), r.patient_id.c_str(), r.name.c_str(),
                r.birth_date.c_str(), r.sex.c_str(), ll(r.study_count));
}

void list_studies(const Archive& archive, bool json) {
  auto rows = archive.studies();
  if (json) return print_json(rows);
  std::printf("%-5s %-7s %-9s %-30s %-6s %s\n", "id", "patient", "date", "description", "series", "study uid");
  for (const auto& r : rows)
    std::printf("%-5lld %-7lld %-9s %-30s %-6lld %s\n", ll(r.id), ll(r.patient), r.date.c_str(), r.description.c_str(),
                ll(r.series_count), r.study_uid.c_str());
}

void list_series(const Archive& archive, bool json) {
  auto rows = archive.series();
  if (json) return print_json(rows);
  std::printf("%-5s %-5s %-4s %-4s %-24s %-9s %-13s %-8s %s\n", "id", "study", "mod", "no", "description",
              "rows x cols", "spacing mm", "slices", "series uid");
  for (const auto& r : rows) {
    std::string size = std::to_string(r.rows.value_or(0)) + "x" + std::to_string(r.columns.value_or(0));
    std::string spacing = millimetres(r.pixel_spacing_row) + "/" + millimetres(r.pixel_spacing_column) + "/" +
                          millimetres(r.slice_thickness);
    std::printf("%-5lld %-5lld %-4s %-4s %-24s %-11s %-13s %-8lld %s\n", ll(r.id), ll(r.study), r.modality.c_str(),
                r.number ? std::to_string(*r.number).c_str() : "-", r.description.c_str(), size.c_str(),
                spacing.c_str(), ll(r.instance_count), r.series_uid.c_str());
  }
}

// With each case, what the orientation check of its CT said (records/orientation_record.h):
// CONTRADICTS marks a case whose header disagrees with the anatomy and is not yet confirmed.
void list_cases(const Archive& archive, bool json) {
  auto rows = archive.cases();
  std::vector<int64_t> ids;
  for (const auto& r : rows) ids.push_back(r.id);
  const auto orientations = records::latest_orientations(archive, ids);
  auto orientation_of = [&](int64_t id) {
    const auto found = orientations.find(id);
    return records::orientation_summary(found == orientations.end() ? nullptr : &found->second);
  };
  if (json) {
    Json list = Json::array();
    for (const auto& r : rows) {
      Json row = to_json(r);
      row["orientation"] = orientation_of(r.id);
      list.push_back(row);
    }
    std::cout << json_text(list) << "\n";
    return;
  }
  std::printf("%-5s %-7s %-12s %-20s %s\n", "id", "patient", "label", "created", "orientation");
  for (const auto& r : rows)
    std::printf("%-5lld %-7lld %-12s %-20s %s\n", ll(r.id), ll(r.patient), r.label.c_str(), r.created_at.c_str(),
                orientation_of(r.id).c_str());
}

void list_flags(const Archive& archive, bool json) {
  auto rows = archive.identity_flags();
  if (json) return print_json(rows);
  std::printf("%-5s %-7s %-10s %-24s %-24s %s\n", "id", "patient", "attribute", "archived", "arrived", "file");
  for (const auto& r : rows)
    std::printf("%-5lld %-7lld %-10s %-24s %-24s %s\n", ll(r.id), ll(r.patient), r.attribute.c_str(),
                r.archived_value.c_str(), r.arrived_value.c_str(), r.source_path.c_str());
}

}  // namespace

void attach_list(CLI::App& app, CommandContext& ctx) {
  auto what = std::make_shared<std::string>("patients");
  app.add_option("what", *what, "patients (default), studies, series, cases or flags (identity flags)")
      ->check(CLI::IsMember({"patients", "studies", "series", "cases", "flags"}));
  app.callback([what, &ctx] {
    Archive archive = Archive::open(resolve_archive_dir(ctx.global));
    bool json = ctx.global.json;
    if (*what == "patients")
      list_patients(archive, json);
    else if (*what == "studies")
      list_studies(archive, json);
    else if (*what == "series")
      list_series(archive, json);
    else if (*what == "cases")
      list_cases(archive, json);
    else
      list_flags(archive, json);
  });
}

}  // namespace maxillo::cli
