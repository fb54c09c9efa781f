#pragma once
// A case's dental scans in the archive (issue 30): each arch's scan as imported ("dental-scan",
// PLY in the scanner's frame, never changed), and its registration onto the CT's teeth
// ("dental-registration", JSON: the pose from the scan's frame into the CT's, and the fit).
// Like landmark sets, nothing is overwritten: importing an arch again adds a newer version and
// the history keeps every one; a registration names the scan it placed, so one made for an
// older scan is never taken for the current one's.
#include <Eigen/Geometry>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "archive/archive.h"
#include "core/json.h"
#include "core/triangle_mesh.h"

namespace maxillo::records {

enum class DentalArch { kUpper, kLower };
inline constexpr DentalArch kBothArches[] = {DentalArch::kUpper, DentalArch::kLower};
std::string_view name_of(DentalArch arch);  // "upper", "lower"

struct StoredDentalScan {
  int64_t artefact_id = 0;
  DentalArch arch = DentalArch::kUpper;
  std::string source;  // the name of the file it came from (not its folder)
  std::string object_sha256;
  std::string created_at;
  int version = 1;                    // 1 = the arch's first scan, 2 = the one that replaced it, ...
  std::vector<std::string> warnings;  // what the import noticed and let pass (holes, non-manifold edges)
  bool already_stored = false;        // store_dental_scan found it as the arch's newest version
};

// Stores the scan (mm, its scanner's frame) as the arch's newest version, unless that version
// holds the same mesh already (then it is returned, already_stored): importing a file twice
// makes one version, as archiving a DICOM file twice makes one instance.
StoredDentalScan store_dental_scan(Archive& archive, int64_t case_id, DentalArch arch, const TriangleMesh& scan,
                                   const std::string& source, const std::vector<std::string>& warnings);

// The arch's newest scan, and every version oldest first.
std::optional<StoredDentalScan> latest_dental_scan(const Archive& archive, int64_t case_id, DentalArch arch);
std::vector<StoredDentalScan> dental_scan_history(const Archive& archive, int64_t case_id, DentalArch arch);
TriangleMesh load_dental_scan(const Archive& archive, const StoredDentalScan& scan);

// Where a registration put a scan and how well it lies on the CT's teeth there.
struct DentalRegistrationRecord {
  DentalArch arch = DentalArch::kUpper;
  int64_t scan_artefact_id = 0;  // the scan placed
  int64_t series_id = 0;         // the CT it was placed into
  Eigen::Isometry3d scan_to_ct = Eigen::Isometry3d::Identity();
  double on_teeth_share = 0;                            // of the scan within 0.5 mm of the CT's teeth
  double rms_mm = 0, p95_mm = 0, within_0_3_share = 0;  // over that part
  double confidence = 0;                                // 1 - the best other pose's share / this one's
  std::string start;  // how the search began: "landmarks and principal axes", "principal axes"
  double seconds = 0;
};

Json to_json(const DentalRegistrationRecord& record);
// Error(kArchiveCorrupt, subject) for a document that is not one.
DentalRegistrationRecord read_dental_registration(const Json& json, const std::string& subject);

// Stores the record under `key` (records/derivation.h: the scan's and the CT's content, the options).
void store_dental_registration(Archive& archive, int64_t case_id, const DentalRegistrationRecord& record,
                               const std::string& key);

struct StoredDentalRegistration {
  DentalRegistrationRecord record;
  std::string key;     // its inputs' key: the pictures of the fit are stored under it
  std::string source;  // the artefact, for errors ("artefact 12 (dental-registration)")
};

// The arch's registration of its newest scan, if it has one.
std::optional<StoredDentalRegistration> current_dental_registration(const Archive& archive, int64_t case_id,
                                                                    DentalArch arch);

// The jaw's augmented dentition (casework/occlusion/augmented_model.h) made with the arch's current
// registration, if there is one: the CT's teeth with the scanned crowns, LPS mm, closed.
std::optional<TriangleMesh> current_augmented_dentition(const Archive& archive, int64_t case_id, DentalArch arch);

// Everything the report shows of a case's dental scans: each arch's newest scan, its current
// registration and the picture of its fit (object file), when there are.
struct CaseDentalArch {
  StoredDentalScan scan;
  std::optional<StoredDentalRegistration> registration;
  std::optional<std::filesystem::path> fit_picture;
};
struct CaseDentalScans {
  std::vector<CaseDentalArch> arches;
  std::vector<std::filesystem::path> augmented_pictures;  // the augmented model's (object files), frontal first
};
CaseDentalScans case_dental_scans(const Archive& archive, int64_t case_id);

// The name the picture of an arch's fit is stored under ("dental-fit-upper").
std::string fit_picture_name(DentalArch arch);

}  // namespace maxillo::records
