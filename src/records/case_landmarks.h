#pragma once
// Landmark sets attached to a case, stored in the archive as 3D Slicer markups (LPS) objects,
// one "landmarks" artefact per stored set. A set may belong to a time point (pre-operative, end
// of distraction, 6 months, ...: a free label and an ISO date), recorded in the artefact's
// parameters JSON: {"source", "count", "frame", "time_point", "date"}. Nothing is overwritten:
// attaching a set again for a time point adds a newer version; the history keeps every one.
//
// A set whose coordinates came from a 2D cephalogram is stored as given (x, y in the image
// plane, z = 0; see ceph/sagittal_projection.h): "frame" then says "cephalogram" and the
// parameters carry the CephalogramAxes used to read it.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "archive/archive.h"
#include "ceph/landmark.h"
#include "ceph/sagittal_projection.h"

namespace maxillo::records {

struct TimePoint {
  std::string label;  // free text, e.g. "pre", "post-distraction", "6M"; "" = no time point
  std::string date;   // "YYYY-MM-DD" or "" (unknown)
};

// How the stored coordinates are to be read.
struct LandmarkFrame {
  LandmarkGeometry geometry = LandmarkGeometry::kVolumeLps;
  CephalogramAxes axes;  // used when geometry is kCephalogram
};

// Where a stored set's points come from, besides the automatic detection: given (a file, `ceph
// add`: a person's reading) or a reference (a truth known by construction, such as a phantom's
// design, kept to measure a detection against and never worked with).
enum class LandmarkOrigin { kGiven, kReference };

// Stores the set and records it as a "landmarks" artefact of the case; `source` says where the
// points came from (a file name, "phantom (analytic)", ...).
void attach_landmarks(Archive& archive, int64_t case_id, const LandmarkSet& landmarks, const std::string& source);
// The same for a time point. Error(kBadValue, date) when the date is not "YYYY-MM-DD" or empty.
void attach_landmarks(Archive& archive, int64_t case_id, const LandmarkSet& landmarks, const std::string& source,
                      const TimePoint& time_point, const LandmarkFrame& frame = {},
                      LandmarkOrigin origin = LandmarkOrigin::kGiven);

// The landmarks of preferred_landmarks; empty when there are none.
LandmarkSet latest_landmarks(const Archive& archive, int64_t case_id);
// The same, among the case's artefacts already read (archive.artefacts(case_id)).
LandmarkSet latest_landmarks(const Archive& archive, const std::vector<ArtefactRecord>& artefacts);

// What an automatic detection (`maxillo landmarks detect`) said of the set beside the points:
// kept in the artefact's parameters ("automatic") so that planning can refuse the flagged ones
// and the report can show every doubt.
struct AutomaticFacts {
  std::string method;                          // e.g. "maxillo-landmarks 1"
  std::map<std::string, double> confidence;    // label -> 0..1 (present landmarks)
  std::map<std::string, std::string> flagged;  // label -> why (its failed checks, or weak evidence)
  std::map<std::string, std::string> absent;   // label -> why it is not in the set
};

struct StoredLandmarks {
  int64_t artefact_id = 0;
  TimePoint time_point;
  LandmarkFrame frame;
  std::string source;
  std::string created_at;
  int version = 1;  // 1 = first set stored for this time point, 2 = its first revision, ...
  LandmarkSet landmarks;
  std::optional<AutomaticFacts> automatic;  // set for a detected set, empty for one given by hand
  bool reference = false;                   // a known truth kept to measure against (never worked with)
};

// Stores a detected set (its present landmarks) with the facts of its detection; its source is
// "automatic (<method>)".
void attach_automatic_landmarks(Archive& archive, int64_t case_id, const LandmarkSet& present,
                                const AutomaticFacts& facts);

// The set a case works with: the newest set given by hand (a file, `ceph add`), which always
// takes precedence, else the newest automatic set; reference sets are never chosen. nullopt when
// the case has none.
std::optional<StoredLandmarks> preferred_landmarks(const Archive& archive, int64_t case_id);

// The newest reference set of the case's CT (LandmarkOrigin::kReference, no time point), nullopt
// when it has none.
std::optional<StoredLandmarks> newest_reference_landmarks(const Archive& archive, int64_t case_id);

// The newest automatic set of the case (whether or not a set given by hand takes precedence).
std::optional<StoredLandmarks> newest_automatic_landmarks(const Archive& archive, int64_t case_id);

// Every stored set of the case, oldest first (the history).
std::vector<StoredLandmarks> landmark_history(const Archive& archive, int64_t case_id);
// The newest version of each time point (sets without a time point are left out), ordered by
// date (undated last), then label.
std::vector<StoredLandmarks> landmark_time_points(const Archive& archive, int64_t case_id);

// "YYYY-MM-DD" with a month 01-12 and a day 01-31.
bool is_iso_date(const std::string& text);

}  // namespace maxillo::records
