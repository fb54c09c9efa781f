#include "casework/occlusion/case_dental_scans.h"

#include <algorithm>
#include <chrono>
#include <functional>

#include "casework/occlusion/augmented_model.h"
#include "casework/occlusion/dental_views.h"
#include "ceph/landmark_frame.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/parallel_slabs.h"
#include "core/temporary_folder.h"
#include "dental/arch_registration.h"
#include "geometry/mesh_measures.h"
#include "geometry/mesh_transform.h"
#include "imaging/hounsfield_reading.h"
#include "imaging/label_crop.h"
#include "imaging/segmentation.h"
#include "mesh/mesh_io.h"
#include "mesh/surface_extraction.h"
#include "records/archived_series.h"
#include "records/case_landmarks.h"
#include "records/derivation.h"
#include "records/mesh_artefact.h"
#include "records/stored_artefact.h"
#include "report/number_text.h"
#include "sample/phantom.h"

namespace maxillo::casework {
namespace {

using records::DentalArch;

constexpr double kSmallestArchMm = 20, kLargestArchMm = 150;

int64_t degenerate_triangles(const TriangleMesh& mesh) {
  int64_t count = 0;
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.faces(f, 0)).transpose();
    const Eigen::Vector3d b = mesh.vertices.row(mesh.faces(f, 1)).transpose();
    const Eigen::Vector3d c = mesh.vertices.row(mesh.faces(f, 2)).transpose();
    count += (b - a).cross(c - a).norm() < 1e-12;
  }
  return count;
}

// The arch's landmarks in the CT, when the set has the incisor and both first molars.
std::optional<dental::ArchLandmarks> arch_landmarks(const LandmarkSet& landmarks, DentalArch arch) {
  const bool upper = arch == DentalArch::kUpper;
  const auto incisor = find_landmark(landmarks, upper ? "U1" : "L1");
  const auto right = find_landmark(landmarks, upper ? "U6R" : "L6R");
  const auto left = find_landmark(landmarks, upper ? "U6L" : "L6L");
  if (!incisor || !right || !left) return std::nullopt;
  return dental::ArchLandmarks{*incisor, *right, *left};
}

// The pose search for one arch: the landmarks' starts when there are any, the global search always.
struct PoseSearch {
  dental::ArchRegistration registration;
  std::string start;
};

PoseSearch search_pose(const TriangleMesh& scan, const TriangleMesh& teeth, const LandmarkSet& landmarks,
                       DentalArch arch) {
  std::vector<Eigen::Isometry3d> starts;
  std::string start = "principal axes";
  if (const auto points = arch_landmarks(landmarks, arch)) try {
      starts = dental::landmark_starts(scan, *points);
      start = "dental landmarks and principal axes";
    } catch (const Error& e) {
      log::warning("dental landmarks of the ", name_of(arch), " arch not used: ", e.reason());
    }
  return {dental::register_arch(scan, teeth, starts), start};
}

// How much of the scan lies on the other jaw's teeth when registered onto them; nullopt when it
// does not fit there either.
std::optional<double> share_on_other_jaw(const TriangleMesh& scan, const CtTeeth& teeth, const LandmarkSet& landmarks,
                                         DentalArch other) {
  try {
    return search_pose(scan, teeth.of(other), landmarks, other).registration.fit.on_teeth_share;
  } catch (const Error& e) {
    if (e.code() != ErrorCode::kProcessing) throw;
    return std::nullopt;
  }
}

std::string swapped_reason(DentalArch arch, DentalArch other, const std::string& own_share, double other_share) {
  return "it fits the CT's " + std::string(name_of(other)) + " teeth (" + report::fixed(100 * other_share, 0) +
         " % of it on them) better than its " + std::string(name_of(arch)) + " teeth (" + own_share +
         "): were the upper and lower scans swapped? Import them again with --upper and --lower the other way round";
}

// The registration of one arch, or an error naming it: its file, what went wrong, and whether the
// scan fits the other jaw's teeth better (the two scans swapped). Both jaws are always tried: an
// arch turned over may lie on the other jaw's teeth well enough to pass for a fit.
PoseSearch register_or_explain(const records::StoredDentalScan& stored, const TriangleMesh& scan, const CtTeeth& teeth,
                               const LandmarkSet& landmarks) {
  const DentalArch other = stored.arch == DentalArch::kUpper ? DentalArch::kLower : DentalArch::kUpper;
  const std::string subject = std::string(name_of(stored.arch)) + " arch scan " + stored.source;
  const std::optional<double> other_share = share_on_other_jaw(scan, teeth, landmarks, other);
  try {
    PoseSearch own = search_pose(scan, teeth.of(stored.arch), landmarks, stored.arch);
    if (other_share && *other_share > own.registration.fit.on_teeth_share)
      throw Error(ErrorCode::kProcessing, subject,
                  swapped_reason(stored.arch, other, report::fixed(100 * own.registration.fit.on_teeth_share, 0) + " %",
                                 *other_share));
    return own;
  } catch (const Error& e) {
    if (e.code() != ErrorCode::kProcessing || e.subject() == subject) throw;
    if (other_share)
      throw Error(ErrorCode::kProcessing, subject, swapped_reason(stored.arch, other, "no fit", *other_share));
    throw Error(ErrorCode::kProcessing, subject, e.reason());
  }
}

records::DentalRegistrationRecord to_record(const records::StoredDentalScan& scan, int64_t series,
                                            const PoseSearch& search, double seconds) {
  const dental::ArchFit& fit = search.registration.fit;
  records::DentalRegistrationRecord record;
  record.arch = scan.arch;
  record.scan_artefact_id = scan.artefact_id;
  record.series_id = series;
  record.scan_to_ct = fit.transform;
  record.on_teeth_share = fit.on_teeth_share;
  record.rms_mm = fit.rms_mm;
  record.p95_mm = fit.p95_mm;
  record.within_0_3_share = fit.within_0_3_share;
  record.confidence = search.registration.confidence;
  record.start = search.start;
  record.seconds = seconds;
  return record;
}

// One arch registered (or an error naming it) and its jaw's augmented dentition made.
ArchRegistrationOutcome register_and_augment(const records::StoredDentalScan& stored, const TriangleMesh& scan,
                                             const CtTeeth& teeth, const LandmarkSet& landmarks, int64_t series,
                                             const Volume& ct, const CaseTissues& jaws) {
  const auto clock = std::chrono::steady_clock::now();
  ArchRegistrationOutcome outcome;
  outcome.scan = stored;
  const PoseSearch search = register_or_explain(stored, scan, teeth, landmarks);
  outcome.record = to_record(stored, series, search,
                             std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count());
  outcome.placed = transformed(scan, outcome.record.scan_to_ct);
  const DentalArch other = stored.arch == DentalArch::kUpper ? DentalArch::kLower : DentalArch::kUpper;
  outcome.augmented =
      augmented_arch(ct, jaws, stored.arch, teeth.of(stored.arch), teeth.of(other), outcome.placed).surface;
  return outcome;
}

// What a registration depends on: the scan, the CT and the landmarks its starts came from.
std::string registration_key(const records::StoredDentalScan& scan, const std::string& ct_hash,
                             const LandmarkSet& landmarks) {
  Json starts = Json::array();
  if (const auto points = arch_landmarks(landmarks, scan.arch))
    for (const Eigen::Vector3d& p : {points->incisor, points->right_molar, points->left_molar})
      starts.push_back({p.x(), p.y(), p.z()});
  return records::derivation_key({scan.object_sha256, ct_hash},
                                 {{"arch", name_of(scan.arch)}, {"landmark_starts", starts}});
}

}  // namespace

std::vector<std::string> check_arch_scan(const TriangleMesh& scan, const std::string& subject) {
  if (scan.face_count() == 0 || scan.vertex_count() < 3)
    throw Error(ErrorCode::kBadValue, subject, "it holds no triangles: not a dental scan");
  const Eigen::Vector3d extent = scan.vertices.colwise().maxCoeff() - scan.vertices.colwise().minCoeff();
  const double across = extent.maxCoeff();
  if (across < kSmallestArchMm)
    throw Error(ErrorCode::kBadValue, subject,
                "it spans only " + report::fixed(across, 1) +
                    " units across, and a dental arch spans 35-80 mm: is it in centimetres? maxillo reads dental "
                    "scans in millimetres");
  if (across > kLargestArchMm)
    throw Error(ErrorCode::kBadValue, subject,
                "it spans " + report::fixed(across, 0) +
                    " units across, and a dental arch spans 35-80 mm: is it in micrometres, or not a dental scan? "
                    "maxillo reads dental scans in millimetres");
  std::vector<std::string> warnings;
  const EdgeCounts edges = count_edges(scan);
  if (edges.non_manifold > 0)
    warnings.push_back(std::to_string(edges.non_manifold) + " non-manifold edges (shared by three or more triangles)");
  if (edges.inconsistent > 0)
    warnings.push_back(std::to_string(edges.inconsistent) + " edges between triangles facing opposite ways");
  if (const int64_t degenerate = degenerate_triangles(scan); degenerate > 0)
    warnings.push_back(std::to_string(degenerate) + " triangles without area");
  return warnings;
}

std::vector<records::StoredDentalScan> import_dental_scans(Archive& archive, int64_t case_id,
                                                           const std::vector<DentalScanFile>& files) {
  struct Checked {
    DentalArch arch;
    TriangleMesh scan;
    std::string source;
    std::vector<std::string> warnings;
  };
  std::vector<Checked> checked;
  for (const DentalScanFile& file : files) {
    TriangleMesh scan = read_mesh(file.file);
    auto warnings = check_arch_scan(scan, file.file.string());
    checked.push_back({file.arch, std::move(scan), file.file.filename().string(), std::move(warnings)});
  }
  std::vector<records::StoredDentalScan> stored;
  for (const Checked& c : checked)
    stored.push_back(records::store_dental_scan(archive, case_id, c.arch, c.scan, c.source, c.warnings));
  return stored;
}

CtTeeth ct_teeth_surfaces(const Volume& hu, const CaseTissues& tissues) {
  const auto upper = uint8_t(Tissue::kUpperTooth), lower = uint8_t(Tissue::kLowerTooth);
  const VoxelBox box = box_of_labels(tissues.jaws, {upper, lower}, 2, "the CT's teeth");
  const Volume ct = cropped(hu, box);
  const LabelVolume jaws = cropped(tissues.jaws, box);
  SurfaceOptions options;
  options.keep_largest_components = 0;  // every tooth
  options.grid = SurfaceGrid::Native;   // the CT's own voxels: a tooth is a few of them across
  const double teeth_hu = SegmentationOptions{}.teeth_hu;
  return {extract_region_surface(ct, jaws, {upper, upper}, teeth_hu, options),
          extract_region_surface(ct, jaws, {lower, lower}, teeth_hu, options)};
}

DentalRegistrationJob prepare_dental_registration(Archive& archive, int64_t case_id, const CaseTissues* tissues) {
  DentalRegistrationJob job;
  job.case_id = case_id;
  job.given_tissues = tissues;
  std::vector<records::StoredDentalScan> scans;
  for (DentalArch arch : records::kBothArches)
    if (auto scan = records::latest_dental_scan(archive, case_id, arch)) scans.push_back(*scan);
  if (scans.empty())
    throw Error(ErrorCode::kNotFound, "case " + std::to_string(case_id),
                "it has no dental scans: import them first with `maxillo dental import`");
  job.landmarks = records::latest_landmarks(archive, case_id);
  if (job.landmarks.empty())
    throw Error(ErrorCode::kNotFound, "case " + std::to_string(case_id),
                "it has no landmarks to tell the CT's upper teeth from the lower: find them first with `maxillo "
                "landmarks detect` (--store)");
  job.series = records::primary_series(archive.case_contents(case_id));
  job.ct_hash = records::series_content_hash(archive, job.series);
  const auto artefacts = archive.artefacts(case_id);

  // The fits stored already under the same inputs; the CT is read and traced only for the others.
  for (const records::StoredDentalScan& stored : scans) {
    const std::string key = registration_key(stored, job.ct_hash, job.landmarks);
    const ArtefactRecord* done = records::newest_with_key(artefacts, ArtefactKind::kDentalRegistration, key);
    if (!done) {
      job.to_register.push_back(stored);
      job.scans.push_back(records::load_dental_scan(archive, stored));
      continue;
    }
    ArchRegistrationOutcome outcome;
    outcome.scan = stored;
    outcome.record =
        records::read_dental_registration(records::artefact_json(archive, *done), records::artefact_source(*done));
    outcome.reused = true;
    if (outcome.record.scan_artefact_id != stored.artefact_id) {
      // The same mesh imported again as a newer version after another one: the fit holds for it.
      outcome.record.scan_artefact_id = stored.artefact_id;
      records::store_dental_registration(archive, case_id, outcome.record, key);
    }
    outcome.placed = transformed(records::load_dental_scan(archive, stored), outcome.record.scan_to_ct);
    if (const ArtefactRecord* augmented = records::newest_with_key(artefacts, ArtefactKind::kAugmentedDentition, key))
      outcome.augmented = records::load_mesh_artefact(archive, *augmented);
    job.result.arches.push_back(std::move(outcome));
  }
  if (!job.to_register.empty()) job.ct = records::load_archived_series(archive, job.series);
  return job;
}

void compute_dental_registration(DentalRegistrationJob& job) {
  if (job.to_register.empty()) return;
  // Segmented before the conversion to HU, as every case is (casework/surfaces/case_tissues.h converts inside).
  if (!job.given_tissues) job.segmented = segment_case_tissues(job.ct, job.landmarks);
  const CaseTissues& jaws = job.given_tissues ? *job.given_tissues : job.segmented;
  if (std::optional<Volume> converted = in_hounsfield_units(job.ct))  // a cone-beam scan's grey values as HU
    job.ct = std::move(*converted);
  job.teeth = ct_teeth_surfaces(job.ct, jaws);
  // Each arch's registration and augmented dentition touch nothing shared: the arches run at once.
  job.computed.assign(job.to_register.size(), {});
  job.failed.assign(job.to_register.size(), std::nullopt);
  std::vector<std::function<void()>> tasks;
  for (size_t a = 0; a < job.to_register.size(); ++a)
    tasks.push_back([&job, &jaws, a] {
      try {
        job.computed[a] =
            register_and_augment(job.to_register[a], job.scans[a], job.teeth, job.landmarks, job.series, job.ct, jaws);
      } catch (const Error& e) {
        job.failed[a] = e;
      }
    });
  run_concurrently(tasks);
}

CaseDentalRegistration store_dental_registration(Archive& archive, DentalRegistrationJob& job) {
  CaseDentalRegistration result = std::move(job.result);
  const AnatomicalFrame frame = anatomical_frame(job.landmarks);
  std::optional<Error> failure;
  for (size_t a = 0; a < job.computed.size(); ++a) {
    if (job.failed[a]) {
      if (!failure) failure = job.failed[a];
      continue;
    }
    ArchRegistrationOutcome& outcome = job.computed[a];
    const DentalArch arch = outcome.scan.arch;
    const std::string key = registration_key(outcome.scan, job.ct_hash, job.landmarks);
    TemporaryFolder scratch("maxillo-dental");
    const auto png = scratch / (records::fit_picture_name(arch) + ".png");
    render_dental_fit(outcome.placed, job.teeth.of(arch), arch, frame, png);
    records::store_picture(archive, job.case_id, ArtefactKind::kDentalRender, key, png);
    records::store_mesh_artefact(archive, job.case_id, kind_name(ArtefactKind::kAugmentedDentition), key,
                                 Json{{"arch", name_of(arch)}}, outcome.augmented);
    records::store_dental_registration(archive, job.case_id, outcome.record, key);  // last: it marks a complete set
    result.arches.push_back(std::move(outcome));
  }
  std::sort(result.arches.begin(), result.arches.end(),
            [](const auto& a, const auto& b) { return a.scan.arch < b.scan.arch; });  // upper first
  if (!job.computed.empty()) store_augmented_pictures(archive, job.case_id, result, frame);
  if (failure) throw *failure;
  return result;
}

CaseDentalRegistration register_case_dental_scans(Archive& archive, int64_t case_id, const CaseTissues* tissues) {
  DentalRegistrationJob job = prepare_dental_registration(archive, case_id, tissues);
  compute_dental_registration(job);
  return store_dental_registration(archive, job);
}

}  // namespace maxillo::casework
