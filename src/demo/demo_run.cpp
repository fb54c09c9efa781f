#include "demo/demo_run.h"

#include <algorithm>
#include <optional>

#include "archive/archive_location.h"
#include "casework/landmarks/automatic_landmarks.h"
#include "casework/occlusion/case_dental_scans.h"
#include "casework/softtissue/case_simulation.h"
#include "casework/sample/phantom_dental_scans.h"
#include "casework/surfaces/case_surfaces.h"
#include "casework/plan/plan_case.h"
#include "casework/plan/planned_case.h"
#include "casework/sample/sample_case.h"
#include "casework/validation/synthetic_postop_case.h"
#include "casework/validation/validation_json.h"
#include "consultation/consultation_report.h"
#include "consultation/report_dicom.h"
#include "core/error.h"
#include "core/parallel_slabs.h"
#include "core/temporary_folder.h"
#include "demo/phantom_occlusion.h"
#include "dental/arch_registration.h"
#include "demo/stage_clock.h"
#include "followup/ceph_sample_cohort.h"
#include "followup/cohort_report.h"
#include "imaging/volume_assembly.h"
#include "landmarking/landmark_detection.h"
#include "net/loopback_server.h"
#include "net/store_client.h"
#include "nightly/nightly.h"
#include "records/archived_series.h"
#include "records/derivation.h"
#include "records/case_landmarks.h"
#include "records/cohort_archive.h"
#include "records/validation_archive.h"

namespace maxillo::demo {
namespace {

// The files of a folder, in name order.
std::vector<std::filesystem::path> files_in(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Sends `files` as `sender` to a storage server of ours on a free loopback port that archives
// into `archive_dir` as `receiver` (the clinic's path: a scanner pushing to maxillo, maxillo
// pushing the report to the PACS). Throws unless every file was sent and archived.
net::StorageServerCounts push_over_dicom(const std::vector<std::filesystem::path>& files, const std::string& sender,
                                         const std::string& receiver, const std::filesystem::path& archive_dir) {
  // An archive on a PostgreSQL server has no folder of this machine's to receive into.
  std::optional<TemporaryFolder> spool;
  if (names_index_server(archive_dir.string())) spool.emplace("demo-spool");
  net::StorageServerOptions server;
  server.archive = archive_dir;
  if (spool) server.spool = spool->path();
  server.ae_title = receiver;
  server.allowed = {{sender, "127.0.0.1"}};
  net::StoreOptions store;
  store.calling_ae = sender;
  store.progress = ProgressDisplay::Never;
  const auto counts = net::with_loopback_server(server, [&](const net::DicomPeer& peer) {
    const auto sent = net::send_files(peer, files, store);
    if (!sent.failures.empty())
      throw Error(ErrorCode::kProcessing, sent.failures.front().file.string(), sent.failures.front().reason);
  });
  if (counts.stored + counts.already_archived != int64_t(files.size()))
    throw Error(ErrorCode::kProcessing, archive_dir.string(), "not every instance sent over DICOM was archived");
  return counts;
}

// The plan applied, and beside it on the other core the CT's skin and bone surfaces, which every
// later stage reads: both start from one segmentation. The archive stays on this thread; the
// surfaces are stored when both are done (unless they already were).
casework::CasePlanResult plan_beside_surfaces(Archive& archive, int64_t case_id, const std::filesystem::path& out) {
  const int64_t series = records::primary_series(archive.case_contents(case_id));
  const Volume ct = records::load_archived_series(archive, series);
  const casework::CaseTissues tissues = casework::segment_case_tissues(ct, records::latest_landmarks(archive, case_id));
  const casework::SurfaceRecipe recipe;
  std::optional<casework::CaseSurfaces> surfaces = casework::stored_case_surfaces(archive, case_id, series, recipe);
  const bool extract = !surfaces;
  casework::CasePlanResult plan;
  run_concurrently({[&] { plan = casework::apply_case_plan(archive, case_id, out, &tissues); },
                    [&] {
                      if (extract)
                        surfaces = casework::extract_case_surfaces(ct, recipe, nullptr,
                                                                   tissues.ct_labels_for(recipe.segmentation));
                    }});
  if (extract) casework::store_case_surfaces(archive, case_id, series, *surfaces, recipe);
  return plan;
}

}  // namespace

Json run_demo(const DemoOptions& options) {
  StageClock clock;
  std::filesystem::create_directories(options.out);
  auto sample = casework::write_sample_case(options.skeletal_class, 1.0, options.out / "sample");
  clock.mark("generate phantom");

  // The phantom arrives as a patient's CT does in a clinic: pushed by the scanner (C-STORE) to
  // `maxillo serve`, here on a loopback port inside this process.
  // Beside the reception, which waits on the network and the disk as much as on the processor,
  // the landmarks are found on the CT without hands (issue 28): the case works with them as with
  // a patient's, and the phantom's known ones are kept beside them as the truth the report
  // measures them against.
  const auto archive_dir = options.archive_dir.empty() ? options.out / "archive" : options.archive_dir;
  net::StorageServerCounts received;
  std::optional<landmarking::LandmarkDetection> detected;
  run_concurrently({[&] { received = push_over_dicom(files_in(sample.ct_folder), "DEMO-CT", "MAXILLO", archive_dir); },
                    [&] {
                      detected = landmarking::detect_landmarks(load_series_volume(files_in(sample.ct_folder)),
                                                               "the phantom's CT");
                    }});
  auto archive = Archive::open(archive_dir);
  clock.mark("receive over DICOM and landmark detection beside it");

  auto case_id = archive.resolve_case(casework::kPhantomPatientId);
  // Dated follow-up (the sample cohort's first patient) for the follow-up table and Wits chart.
  // Those are phantoms' known landmarks, stored as references like the phantom's own: the case
  // works with the detected set, as a patient's would (records::preferred_landmarks).
  records::CohortImportReport follow_up;
  records::attach_cohort_time_points(
      archive, case_id, followup::sample_patient_follow_up(followup::sample_cohort_patients()[0], 2001), {},
      "sample cohort P01 (phantoms)", follow_up, records::LandmarkOrigin::kReference);
  records::attach_automatic_landmarks(archive, case_id, detected->present(), casework::automatic_facts(*detected));
  records::attach_landmarks(archive, case_id, sample.landmarks, "phantom (analytic)", {}, {},
                            records::LandmarkOrigin::kReference);
  // The issue #4 must-show plan: two trans-sinusal distractors, 10 mm advancement, 6 mm widening.
  records::store_plan(archive, case_id,
                      planning::distraction_plan({.advancement_mm = 10, .widening_mm = 6},
                                                 "TS-MD distraction: 10 mm advancement, 6 mm widening"));
  auto plan = plan_beside_surfaces(archive, case_id, options.out / "plan");
  clock.mark("plan, the CT's skin and bone beside it");
  // The patient's dental scans (issue 30): the sample's intraoral scans, each in a scanner's frame
  // of its own, imported and placed onto the CT's teeth without hands; the sample knows where
  // they were taken, which the summary measures the placement against.
  casework::import_dental_scans(archive, case_id,
                                {{records::DentalArch::kUpper, sample.dental_folder / "upper.stl"},
                                 {records::DentalArch::kLower, sample.dental_folder / "lower.stl"}});
  auto dental_job = casework::prepare_dental_registration(archive, case_id, &plan.tissues);
  // The face for the planned move (issue #3): the plan's maxillary move, mass tensor model. The
  // face's tet model is built once here and serves the synthetic post-operative CT and the
  // validation too. Beside the prediction, which holds the archive, the scans' registration and
  // the augmented model are computed, and the occlusion and its splint on the augmented jaws (the
  // scanned crowns on the CT's roots, in the CT's frame: what the teeth meet with are the crowns
  // the scans show); they are stored after.
  const auto planned = casework::load_planned_case(archive, case_id, &plan.tissues);
  casework::SimulationRequest simulation;
  simulation.plan = plan.plan.plan;
  simulation.out = options.out / "soft-tissue";
  simulation.uncertainty = true;
  simulation.face_model = planned.face_model(simulation.options);
  std::optional<casework::SimulationResult> predicted;
  casework::OcclusionRun occlusion;
  run_concurrently({[&] { predicted = casework::simulate_case(archive, case_id, simulation, &plan.tissues); },
                    [&] {
                      casework::compute_dental_registration(dental_job);
                      occlusion = compute_phantom_occlusion(augmented_arches(dental_job));
                    }});
  clock.mark("soft tissue; beside it the dental scans placed and occluded");
  const auto dental = casework::store_dental_registration(archive, dental_job);
  archive_phantom_occlusion(archive, case_id, std::move(occlusion), sample.landmarks, options.out / "occlusion");
  clock.mark("dental scans and occlusion stored");
  // Validation (issue #7): a synthetic post-operative CT with a known error, registered, the
  // bone moves found by ICP, the face predicted for them and compared; then the nightly summary.
  auto postop = casework::make_synthetic_postop_case(archive, case_id, {}, options.out / "postop", true, "", &planned);
  clock.mark("synthetic post-operative CT");
  auto validation = casework::validate_case(archive, case_id, {}, options.out / "validation", &planned);
  records::store_validation(archive, casework::validation_to_store(validation));
  clock.mark("validation");
  nightly::NightlyOptions nightly_options;
  nightly_options.out = options.out / "nightly";
  const auto nightly_run = nightly::run_nightly(archive, nightly_options);
  clock.mark("nightly summary");
  auto report = consultation::write_consultation_report(archive, case_id, options.out / "report.pdf");
  clock.mark("volume, surfaces, views, report");
  // The report back to the PACS (a second server of ours standing in for it), as Encapsulated
  // PDF in the patient's study, as `maxillo send --report` does.
  const auto report_dicom = consultation::write_report_dicom(archive, case_id, report.pdf, options.out / "report.dcm",
                                                             consultation::StoreInArchive::Yes);
  const auto pacs = push_over_dicom({report_dicom.file}, "MAXILLO", "DEMO-PACS", options.out / "pacs");
  clock.mark("report sent to the PACS");
  auto cohort = followup::analyse_cohort(followup::sample_cohort(), {}, ceph::Sex::kUnknown, "sample cohort");
  auto cohort_pdf = options.out / "cohort-followup.pdf";
  int cohort_pages =
      followup::write_cohort_report(cohort, followup::consecutive_pairs(followup::cohort_time_point_labels(cohort)),
                                    "sample cohort (synthetic)", cohort_pdf);
  clock.mark("cohort follow-up");

  double detection_sum = 0;
  int detected_count = 0;
  for (const auto& l : detected->present())
    if (const auto known = find_landmark(sample.landmarks, l.label)) {
      detection_sum += (l.position - *known).norm();
      ++detected_count;
    }
  Json dental_summary = Json::object();
  const auto dental_truth = casework::read_phantom_dental_truth(sample.dental_folder);
  for (const auto& arch : dental.arches) {
    const auto& truth = arch.scan.arch == records::DentalArch::kUpper ? dental_truth.upper : dental_truth.lower;
    dental_summary[std::string(name_of(arch.scan.arch))] = {
        {"on_teeth_share", arch.record.on_teeth_share},
        {"rms_mm", arch.record.rms_mm},
        {"confidence", arch.record.confidence},
        {"distance_from_truth_mm", dental::pose_distance_mm(arch.placed, Eigen::Isometry3d::Identity(),
                                                            truth.scan_to_ct * arch.record.scan_to_ct.inverse())}};
  }
  Json summary{{"report", report.pdf.string()},
               {"dental_scans", dental_summary},
               {"landmarks_detected", detected_count},
               {"landmark_mean_distance_mm", detected_count ? detection_sum / detected_count : 0.0},
               {"pages", report.pages},
               {"archive", archive_dir.string()},
               {"case", case_id},
               {"received_over_dicom", received.stored},
               {"already_archived", received.already_archived},
               {"report_sent_to_pacs", pacs.stored + pacs.already_archived},
               {"pacs_archive", (options.out / "pacs").string()},
               {"surfaces_reused", report.surfaces_reused},
               {"cohort_report", cohort_pdf.string()},
               {"cohort_pages", cohort_pages},
               {"plan_result", plan.result_json.string()},
               {"plan_feasible", plan.result.feasible},
               {"soft_tissue_max_displacement_mm", predicted->views.max_displacement_mm},
               {"validation", validation.summary},
               {"validation_truth", postop.truth},
               {"nightly_summary", nightly_run.summary_pdf.string()},
               {"nightly_pages", nightly_run.summary_pages},
               {"timing", clock.to_json()}};
  return summary;
}

}  // namespace maxillo::demo
