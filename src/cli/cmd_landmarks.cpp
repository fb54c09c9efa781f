// maxillo landmarks detect INPUT [--out FILE.csv|.mrk.json] [--only LABELS] [--store]: the 29 cephalometric
// landmarks found automatically on a head CT (landmarking/landmark_detection.h), each with its
// confidence and the checks it passed or failed. INPUT: a case of the archive (id, case:N or
// Patient ID), a DICOM series folder, or a MetaImage/NRRD volume.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <set>
#include <sstream>

#include "casework/landmarks/automatic_landmarks.h"
#include "cli/command.h"
#include "cli/folder_files.h"
#include "core/error.h"
#include "core/json.h"
#include "imaging/volume_assembly.h"
#include "imaging/volume_file.h"
#include "landmarking/detection_files.h"
#include "records/archived_series.h"
#include "records/case_landmarks.h"
#include "records/derivation.h"

namespace maxillo::cli {
namespace {

struct DetectArguments {
  std::string input;
  std::filesystem::path out;
  std::string only;
  bool store = false;
};

bool is_volume_file(const std::filesystem::path& path) {
  const std::string name = path.filename().string();
  for (const char* suffix : {".mhd", ".mha", ".nrrd", ".nhdr"})
    if (name.size() > std::strlen(suffix) && name.ends_with(suffix)) return true;
  return false;
}

bool names_a_file(const std::string& input) {
  const std::filesystem::path path(input);
  return std::filesystem::is_directory(path) || (std::filesystem::is_regular_file(path) && is_volume_file(path));
}

// The CT named by INPUT: a volume file, a folder of DICOM files, or an archived case.
Volume load_input(const std::string& input, const GlobalOptions& global) {
  const std::filesystem::path path(input);
  if (std::filesystem::is_regular_file(path) && is_volume_file(path)) return read_volume_file(path);
  if (std::filesystem::is_directory(path)) return load_series_volume(files_below(path));
  Archive archive = Archive::open(resolve_archive_dir(global));
  const int64_t case_id = archive.resolve_case(input);
  return records::load_archived_series(archive, records::primary_series(archive.case_contents(case_id)));
}

// Keeps only the labels listed ("S,N,Me"); Error(kBadValue) for a label the method does not know.
void keep_only(landmarking::LandmarkDetection& d, const std::string& only) {
  if (only.empty()) return;
  std::set<std::string> wanted;
  std::stringstream list(only);
  for (std::string label; std::getline(list, label, ',');) {
    if (!d.find(label)) throw Error(ErrorCode::kBadValue, "--only", "unknown landmark label '" + label + "'");
    wanted.insert(label);
  }
  std::erase_if(d.landmarks, [&](const auto& l) { return !wanted.count(l.label); });
}

void print_table(const landmarking::LandmarkDetection& d, double seconds) {
  std::printf("%-5s %9s %9s %9s  %-5s %-8s %s\n", "label", "x", "y", "z", "conf", "status", "checks / note");
  for (const auto& l : d.landmarks) {
    std::string remark = landmarking::failed_checks(l);
    if (!l.note.empty() && remark.find(l.note) == std::string::npos) remark += (remark.empty() ? "" : "; ") + l.note;
    if (l.position)
      std::printf("%-5s %9.2f %9.2f %9.2f  %4.2f  %-8s %s\n", l.label.c_str(), l.position->x(), l.position->y(),
                  l.position->z(), l.confidence, landmarking::status_of(l).c_str(), remark.c_str());
    else
      std::printf("%-5s %9s %9s %9s  %4s  %-8s %s\n", l.label.c_str(), "", "", "", "", "absent", remark.c_str());
  }
  std::printf("head frame: %s; midsagittal asymmetry %.2f mm; grey values: %s; %.1f s\n", d.frame_source.c_str(),
              d.asymmetry_mm, d.reading.describe().c_str(), seconds);
}

// Stores the detected set with the case (beside a set given by hand, which keeps precedence),
// and prints how far each detected landmark lies from the one given by hand.
void store_with_case(const DetectArguments& a, const landmarking::LandmarkDetection& detection,
                     const GlobalOptions& global) {
  Archive archive = Archive::open(resolve_archive_dir(global));
  const int64_t case_id = archive.resolve_case(a.input);
  const auto before = records::preferred_landmarks(archive, case_id);
  records::attach_automatic_landmarks(archive, case_id, detection.present(), casework::automatic_facts(detection));
  if (global.json) return;
  std::printf("stored %zu automatic landmarks with case %lld\n", detection.present().size(),
              static_cast<long long>(case_id));
  if (!before || before->automatic) return;
  std::printf("the set given by hand (%s) keeps precedence; distance of each automatic landmark from it:\n",
              before->source.c_str());
  for (const auto& l : detection.landmarks)
    if (const auto by_hand = find_landmark(before->landmarks, l.label); by_hand && l.position)
      std::printf("  %-5s %6.2f mm\n", l.label.c_str(), (*l.position - *by_hand).norm());
}

int run_detect(const DetectArguments& a, const GlobalOptions& global) {
  const auto start = std::chrono::steady_clock::now();
  if (a.store && names_a_file(a.input))
    throw Error(ErrorCode::kUsage, "--store", "stores with a case of the archive: give a case, not a file");
  const Volume ct = load_input(a.input, global);
  auto detection = landmarking::detect_landmarks(ct, a.input);
  if (a.store) store_with_case(a, detection, global);
  keep_only(detection, a.only);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!a.out.empty()) landmarking::write_detection(a.out, detection);
  if (global.json)
    std::cout << json_text(landmarking::detection_json(detection)) << "\n";
  else
    print_table(detection, seconds);
  return 0;
}

}  // namespace

void attach_landmarks(CLI::App& app, CommandContext& ctx) {
  app.require_subcommand(1);
  auto a = std::make_shared<DetectArguments>();
  CLI::App* detect =
      app.add_subcommand("detect", "find the 29 cephalometric landmarks automatically, with confidences and checks");
  detect->add_option("INPUT", a->input, "case (id, case:N or Patient ID), DICOM series folder, or .mhd/.nrrd volume")
      ->required();
  detect->add_option("--out", a->out, "also write them to FILE.csv (label,x,y,z first) or FILE.mrk.json (3D Slicer)");
  detect->add_option("--only", a->only, "comma-separated labels to report (default: all 29)");
  detect->add_flag("--store", a->store,
                   "keep them with the case as an automatic set (a set given by hand keeps precedence; the distance "
                   "of each from it is printed)");
  detect->callback([a, &ctx] { ctx.exit_code = run_detect(*a, ctx.global); });
}

}  // namespace maxillo::cli
