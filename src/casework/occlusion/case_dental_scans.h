#pragma once
// A patient's dental scans in the case (issue 30): `maxillo dental import` and `maxillo dental
// register`. An arch's scan (an intraoral scan's crowns and gingiva, or a digitised cast's crowns
// and base; STL, PLY or OBJ in mm) is checked and stored as it came (records/dental_scans.h),
// then placed onto the CT's teeth of its own jaw without hands (dental/arch_registration.h):
// from the dental landmarks where the case has them, and from the principal axes' global search
// always. The CT's teeth are traced through the CT's grey values where the segmentation says
// teeth, told apart by jaw with the case's landmarks (planning/jaw_separation.h). Each arch's fit
// is stored with a picture of it: the placed scan over the CT's teeth, coloured by how far each
// point lies from them; and so is the augmented model, the CT's teeth of each jaw with the
// scanned crowns in place of their own (casework/occlusion/augmented_model.h), pictured with the crowns
// coloured apart.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "archive/archive.h"
#include "casework/surfaces/case_tissues.h"
#include "ceph/landmark.h"
#include "core/error.h"
#include "core/volume.h"
#include "core/triangle_mesh.h"
#include "records/dental_scans.h"

namespace maxillo::casework {

struct DentalScanFile {
  records::DentalArch arch = records::DentalArch::kUpper;
  std::filesystem::path file;
};

// Throws Error(kBadValue, subject, reason) for a scan that cannot be an arch in millimetres (no
// triangles; spanning less than 20 or more than 150 units: centimetres, micrometres, or not an
// arch); returns the warnings of what it lets pass (non-manifold edges, inconsistently oriented
// faces, degenerate triangles: the fit uses the surface's points, which these do not spoil).
std::vector<std::string> check_arch_scan(const TriangleMesh& scan, const std::string& subject);

// Reads and checks every file first, then stores each as its arch's newest scan: a bad file
// stores nothing, not even the good one beside it.
std::vector<records::StoredDentalScan> import_dental_scans(Archive& archive, int64_t case_id,
                                                           const std::vector<DentalScanFile>& files);

// The CT's upper and lower teeth (LPS mm, closed surfaces, every tooth kept). `hu`: the CT in
// Hounsfield units (a cone-beam scan converted first: imaging/hounsfield_reading.h).
struct CtTeeth {
  TriangleMesh upper, lower;
  const TriangleMesh& of(records::DentalArch arch) const { return arch == records::DentalArch::kUpper ? upper : lower; }
};
CtTeeth ct_teeth_surfaces(const Volume& hu, const CaseTissues& tissues);

struct ArchRegistrationOutcome {
  records::StoredDentalScan scan;
  records::DentalRegistrationRecord record;
  TriangleMesh placed;     // the scan in the CT's frame
  TriangleMesh augmented;  // the jaw's CT teeth with this scan's crowns in their place (augmented_model.h)
  bool reused = false;     // found stored under the same inputs, not registered again
};

struct CaseDentalRegistration {
  std::vector<ArchRegistrationOutcome> arches;  // upper first, for the arches the case has scans of
};

// Registers each arch's newest scan onto the CT's teeth of its jaw and stores the fit, its
// picture and the jaw's augmented dentition (unless stored already for the same scan, CT and
// program), then pictures of the augmented model (both jaws, frontal and lateral). Throws Error(kNotFound) for
// a case without dental scans or landmarks, Error(kProcessing) naming the arch and its file for
// a poor or ambiguous fit, saying so when the scan fits the other jaw's teeth (upper and lower
// swapped). An arch that fails stores nothing; the other arch's fit is stored before the error.
CaseDentalRegistration register_case_dental_scans(Archive& archive, int64_t case_id,
                                                  const CaseTissues* tissues = nullptr);

// register_case_dental_scans in its three steps, for a caller that runs the work beside other
// work (the demo beside the face prediction): prepare reads the archive (the scans, the stored
// fits, the CT), compute touches nothing but the job (any thread; no archive, no rendering),
// store renders the pictures and writes. The job holds what passes between them.
struct DentalRegistrationJob {
  int64_t case_id = 0, series = 0;
  std::string ct_hash;
  LandmarkSet landmarks;
  CaseDentalRegistration result;  // the reused arches (prepare), then all (store)
  std::vector<records::StoredDentalScan> to_register;
  std::vector<TriangleMesh> scans;  // of to_register, in their scanners' frames
  Volume ct;                        // in HU, when an arch is to be registered
  const CaseTissues* given_tissues = nullptr;
  CaseTissues segmented;                          // compute's, when no tissues were given
  CtTeeth teeth;                                  // compute's
  std::vector<ArchRegistrationOutcome> computed;  // compute's, one per to_register
  std::vector<std::optional<Error>> failed;       // compute's
};
DentalRegistrationJob prepare_dental_registration(Archive& archive, int64_t case_id,
                                                  const CaseTissues* tissues = nullptr);
void compute_dental_registration(DentalRegistrationJob& job);
// Throws the first arch's failure after storing the others.
CaseDentalRegistration store_dental_registration(Archive& archive, DentalRegistrationJob& job);

}  // namespace maxillo::casework
