#include "demo/phantom_occlusion.h"

#include "ceph/landmark_frame.h"
#include "core/error.h"
#include "occlusion/arch_contacts.h"
#include "occlusion/occlusion_benchmark.h"
#include "casework/occlusion/archived_occlusion.h"
#include "render/anatomical_views.h"

namespace maxillo::demo {
namespace {

// The demo's occlusion settings: the phantom's arches by name, and the splint's clearance.
casework::OcclusionRunOptions phantom_occlusion_options() {
  casework::OcclusionRunOptions options;
  options.upper_label = "phantom upper teeth (augmented model)";
  options.lower_label = "phantom lower teeth (augmented model)";
  // The scanned crowns keep ridges sharper than the splint's 0.25 mm grid resolves; a wider
  // clearance keeps the imprints off them.
  options.splint_options.clearance_mm = 0.2;
  return options;
}

}  // namespace

PhantomArches augmented_arches(const casework::CaseDentalRegistration& dental) {
  PhantomArches arches;
  for (const auto& arch : dental.arches)
    (arch.scan.arch == records::DentalArch::kUpper ? arches.upper : arches.lower) = arch.augmented;
  for (const auto& [mesh, name] : {std::pair{&arches.upper, "upper"}, {&arches.lower, "lower"}})
    if (mesh->face_count() == 0)
      throw Error(ErrorCode::kProcessing, "the phantom's dental scans", std::string("no augmented ") + name + " jaw");
  return arches;
}

PhantomArches augmented_arches(const casework::DentalRegistrationJob& job) {
  casework::CaseDentalRegistration computed = job.result;
  for (size_t a = 0; a < job.computed.size(); ++a)
    if (!job.failed[a]) computed.arches.push_back(job.computed[a]);
  return augmented_arches(computed);
}

Eigen::Isometry3d phantom_start_pose(const TriangleMesh& upper) {
  const Eigen::Vector3d centre = upper.vertices.colwise().mean().transpose();
  Eigen::Isometry3d start = Eigen::Isometry3d::Identity();
  start.translate(centre + Eigen::Vector3d(0.8, -1.0, 1.5))
      .rotate(Eigen::AngleAxisd(2.0 * M_PI / 180, Eigen::Vector3d(1, 2, 0.5).normalized()))
      .translate(-centre);
  return start;
}

casework::OcclusionRun compute_phantom_occlusion(const PhantomArches& arches) {
  const DistanceField upper(arches.upper), lower(arches.lower);
  auto pairs = occlusion::contact_spring_pairs(upper, lower, Eigen::Isometry3d::Identity(), 4, 1.0);
  // Where the teeth touch, the arches' surfaces lie up to a few tenths of a millimetre apart: each
  // spring ends where its upper point lies in the registered occlusion, not on the lower
  // surface, so the registered occlusion is the springs' rest position.
  for (occlusion::SpringPair& pair : pairs) pair.lower = pair.upper;
  if (pairs.size() < 4)
    throw Error(ErrorCode::kProcessing, "phantom", "the phantom's arches have fewer than 4 contacts");
  // As the benchmark does: the displaced arch is brought down into contact as deep as the
  // arches touch in the phantom (label surfaces of touching teeth overlap a little), so the
  // engine's "no deeper than the start" rule admits the phantom's own occlusion.
  const double natural_penetration =
      occlusion::assess_contacts(upper, lower, Eigen::Isometry3d::Identity(), 2.0).max_penetration_mm;
  const Eigen::Isometry3d start =
      occlusion::place_in_contact(upper, lower, phantom_start_pose(arches.upper), natural_penetration);
  return casework::compute_occlusion(arches.upper, arches.lower, pairs, start, phantom_occlusion_options());
}

void archive_phantom_occlusion(Archive& archive, int64_t case_id, casework::OcclusionRun run,
                               const LandmarkSet& landmarks, const std::filesystem::path& folder) {
  casework::write_occlusion_outputs(run, folder, phantom_occlusion_options());
  casework::store_occlusion_run(archive, case_id, run, {}, anatomical_frame(landmarks));
}

}  // namespace maxillo::demo
