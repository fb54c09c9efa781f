#include "consultation/consultation_report.h"

#include <algorithm>
#include <chrono>
#include <ctime>

#include "archive/artefact_kind.h"
#include "archive/instance_source.h"
#include "casework/landmarks/case_orientation.h"
#include "core/atomic_file.h"
#include "core/progress.h"
#include "core/utc_time.h"
#include "core/version.h"
#include "casework/landmarks/automatic_landmarks.h"
#include "core/log.h"
#include "records/case_landmarks.h"
#include "sections/cephalometry_section.h"
#include "sections/landmark_section.h"
#include "casework/landmarks/landmark_views.h"
#include "records/derivation.h"
#include "records/plan_archive.h"
#include "sections/planning_section.h"
#include "ceph/landmark_frame.h"
#include "sections/dental_section.h"
#include "sections/occlusion_section.h"
#include "sections/soft_tissue_section.h"
#include "sections/validation_section.h"
#include "report/report_template.h"
#include "report/write_report.h"

namespace maxillo::consultation {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

const StudyRecord* study_of(const CaseContents& contents, int64_t study) {
  for (const auto& s : contents.studies)
    if (s.id == study) return &s;
  return nullptr;
}

// "study description · series description", either part left out when empty.
std::string describe_series(const StudyRecord* study, const SeriesRecord& series) {
  std::string study_text = study ? study->description : "";
  if (study_text.empty()) return series.description;
  return series.description.empty() ? study_text : study_text + " · " + series.description;
}

// How a series reached the archive, from its first instance's recorded source: "over DICOM from
// AE" for what arrived over the network (ImportOptions::source_label), else "from files".
std::string received_by(const Archive& archive, int64_t series) {
  const auto instances = archive.instances(series);
  if (instances.empty()) return "";
  const auto sender = network_sender(instances.front().source_path);
  return sender ? "over DICOM from " + *sender : "from files";
}

// "over DICOM from CT_ROOM2 (1 series); from files (2 series)", in the order first met.
std::string describe_reception(const Archive& archive, const CaseContents& contents) {
  std::vector<std::pair<std::string, int>> ways;
  for (const auto& entry : contents.series) {
    const std::string way = received_by(archive, entry.series.id);
    if (way.empty()) continue;
    auto found = std::find_if(ways.begin(), ways.end(), [&](const auto& w) { return w.first == way; });
    if (found == ways.end())
      ways.emplace_back(way, 1);
    else
      ++found->second;
  }
  std::string text;
  for (const auto& [way, count] : ways)
    text += (text.empty() ? "" : "; ") + way + " (" + std::to_string(count) + " series)";
  return text;
}

report::ReportModel model_header(const Archive& archive, const CaseContents& contents) {
  report::ReportModel model;
  model.patient = {contents.patient.name, contents.patient.patient_id, contents.patient.birth_date,
                   contents.patient.sex};
  model.case_label = contents.record.label;
  model.images_received = describe_reception(archive, contents);
  for (const auto& entry : contents.series) {
    const auto& s = entry.series;
    const StudyRecord* study = study_of(contents, s.study);
    model.series.push_back(
        {study ? study->date : "",
         s.modality,
         describe_series(study, s),
         int(s.instance_count),
         {s.pixel_spacing_column.value_or(0), s.pixel_spacing_row.value_or(0), s.slice_thickness.value_or(0)}});
  }
  model.generated_at = utc_now();
  model.program_version = kVersion;
  return model;
}

// "29 points placed by hand", or how many were found automatically and which are in doubt.
std::string landmark_summary(const std::optional<records::StoredLandmarks>& stored, const std::string& failure) {
  if (!stored || stored->landmarks.empty())
    return failure.empty() ? "none attached" : "none attached; the automatic detection failed: " + failure;
  if (!stored->automatic) return std::to_string(stored->landmarks.size()) + " points (" + stored->source + ")";
  std::string text = std::to_string(stored->landmarks.size()) + " points found automatically (" +
                     stored->automatic->method + "), no landmark file attached";
  if (!stored->automatic->flagged.empty()) {
    text += "; flagged, not for planning until confirmed:";
    for (const auto& [label, why] : stored->automatic->flagged) text += " " + label + " (" + why + ");";
  }
  if (!stored->automatic->absent.empty()) {
    text += " absent:";
    for (const auto& [label, why] : stored->automatic->absent) text += " " + label;
  }
  return text;
}

report::Section summary_section(const CaseContents& contents, int64_t series, const casework::CaseSurfaces& surfaces,
                                const std::string& landmarks, const records::OrientationRecord& orientation) {
  std::string description;
  for (const auto& entry : contents.series)
    if (entry.series.id == series) description = entry.series.description + " (" + entry.role + ")";
  report::KeyValueBlock facts{{
      {"Series analysed", description},
      {"Skin surface", std::to_string(surfaces.skin.face_count()) + " triangles"},
      {"Bone surface", std::to_string(surfaces.bone.face_count()) + " triangles"},
      {"Landmarks", landmarks},
      {"Orientation check",
       orientation.finding +
           (orientation.confirmed_at.empty() ? "" : " Confirmed by hand at " + orientation.confirmed_at + ".")},
  }};
  return {"summary", {facts}};
}

// DICOM Patient's Sex to the sex whose norms apply (Wits differs by sex); "O" and "" have none.
ceph::Sex sex_for_norms(const std::string& dicom_sex) {
  if (dicom_sex == "F") return ceph::Sex::kFemale;
  if (dicom_sex == "M") return ceph::Sex::kMale;
  return ceph::Sex::kUnknown;
}

report::Section views_section(const std::vector<casework::CaseView>& views) {
  report::ImageGrid grid;
  grid.per_row = 3;
  for (const auto& v : views) grid.figures.push_back({v.png, v.caption});
  return {"views", {grid}};
}

// What the archive holds for the case: series with roles, then every derived item and how it
// was made (program version, derivation key).
report::Section contents_section(const Archive& archive, const CaseContents& contents) {
  report::Table series;
  series.columns = {{"series", 0.4},
                    {"role", 0.15},
                    {"modality", 0.15},
                    {"instances", 0.15, report::Align::Right},
                    {"archive id", 0.15, report::Align::Right}};
  for (const auto& entry : contents.series)
    series.rows.push_back({entry.series.description, entry.role, entry.series.modality,
                           std::to_string(entry.series.instance_count), std::to_string(entry.series.id)});
  report::Table derived;
  derived.columns = {{"derived item", 0.25}, {"made (UTC)", 0.3}, {"program", 0.15}, {"derivation key", 0.3}};
  for (const auto& a : archive.artefacts(contents.record.id))
    derived.rows.push_back({a.kind, a.created_at, a.program_version, a.inputs_hash.substr(0, 16)});
  return {"contents", {series, derived}};
}

}  // namespace

ConsultationResult write_consultation_report(Archive& archive, int64_t case_id, const std::filesystem::path& out_pdf,
                                             const ConsultationOptions& options) {
  auto report_template = report::load_report_template(options.template_resource);
  auto contents = archive.case_contents(case_id);
  auto series = records::primary_series(contents);
  ConsultationResult result;
  Progress progress("report", 3);  // surfaces, views, layout: each takes seconds on a real CT

  auto start = Clock::now();
  auto surfaces = casework::case_surfaces(archive, case_id, series, options.surfaces);
  result.surfaces_reused = surfaces.reused;
  result.seconds_surfaces = seconds_since(start);
  progress.advance();

  start = Clock::now();
  // A case without landmarks gets the set detected on its CT (stored, so that the sections
  // below read it); a scan the detection cannot read still gets its report, saying why.
  std::string detection_failure;
  std::optional<records::StoredLandmarks> stored_landmarks;
  try {
    stored_landmarks = casework::case_landmarks(archive, case_id);
  } catch (const Error& e) {
    detection_failure = e.what();
    log::warning("case:", case_id, ": ", detection_failure);
  }
  const LandmarkSet landmarks = stored_landmarks ? stored_landmarks->landmarks : LandmarkSet{};
  auto views = casework::case_views(archive, case_id, surfaces, landmarks, options.views);
  std::vector<casework::LandmarkView> landmark_pictures;
  if (stored_landmarks && !stored_landmarks->landmarks.empty())
    landmark_pictures = casework::landmark_views(archive, case_id, surfaces, *stored_landmarks, options.views);
  result.seconds_views = seconds_since(start);
  progress.advance();

  start = Clock::now();
  auto model = model_header(archive, contents);
  const auto orientation = casework::case_orientation(archive, case_id);
  if (!orientation.trusted())
    model.warning_banner =
        "THE CT HEADER CONTRADICTS THE ANATOMY: LEFT AND RIGHT CANNOT BE TRUSTED (see Summary; not for planning)";
  model.sections.push_back(
      summary_section(contents, series, surfaces, landmark_summary(stored_landmarks, detection_failure), orientation));
  model.sections.push_back(views_section(views));
  if (auto landmarks_page =
          sections::landmark_section(stored_landmarks, records::newest_automatic_landmarks(archive, case_id),
                                     landmark_pictures, records::newest_reference_landmarks(archive, case_id)))
    model.sections.push_back(std::move(*landmarks_page));
  model.sections.push_back(sections::case_cephalometry_section(archive, case_id, sex_for_norms(contents.patient.sex)));
  if (auto dental = sections::dental_section(records::case_dental_scans(archive, case_id)))
    model.sections.push_back(std::move(*dental));
  if (auto plan_result = records::latest_plan_result(archive, case_id))
    model.sections.push_back(sections::planning_section(*plan_result));
  else if (auto plan = records::latest_plan(archive, case_id))
    model.sections.push_back(sections::unapplied_plan_section(
        *plan, case_id,
        stored_landmarks ? casework::flagged_for_planning(*stored_landmarks) : std::vector<std::string>{}));
  if (auto occlusion = records::latest_occlusion(archive, case_id))
    model.sections.push_back(sections::occlusion_section(*occlusion, anatomical_frame(landmarks)));
  if (auto simulation = records::latest_simulation(archive, case_id))
    model.sections.push_back(sections::soft_tissue_section(*simulation));
  if (auto validation = records::latest_validation(archive, case_id))
    model.sections.push_back(sections::validation_section(*validation));
  model.sections.push_back(contents_section(archive, contents));
  result.pages = report::write_report(model, report_template, out_pdf);
  result.pdf = out_pdf;
  result.report_sha256 = archive.store_object(read_file(out_pdf));
  archive.add_artefact(NewArtefact{case_id, kind_name(ArtefactKind::kReport), result.report_sha256, "application/pdf",
                                   records::derivation_key({surfaces.key}, {{"template", options.template_resource}}),
                                   "{}"});
  result.seconds_layout = seconds_since(start);
  progress.advance();
  progress.finish();
  return result;
}

}  // namespace maxillo::consultation
