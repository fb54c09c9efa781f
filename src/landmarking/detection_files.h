#pragma once
// A landmark detection as files and JSON: the CSV (label,x,y,z first, as `maxillo sample`
// writes landmarks, empty coordinates for an absent landmark; then confidence, status and the
// checks), 3D Slicer markups (.mrk.json: absent points with positionStatus "missing", the
// confidence and checks in each point's description), and the --json document.
#include <filesystem>
#include <string>

#include "core/json.h"
#include "landmarking/landmark_detection.h"

namespace maxillo::landmarking {

std::string format_detection_csv(const LandmarkDetection& detection);
std::string format_detection_markups(const LandmarkDetection& detection);
Json detection_json(const LandmarkDetection& detection);

// "ok", "flagged" or "absent".
std::string status_of(const DetectedLandmark& landmark);
// The failed checks as one line ("mirror: 6.2 mm from the mirror image; ..."); for a point found
// with too little evidence and no failed check, "weak evidence" and the finding's note; or "".
std::string failed_checks(const DetectedLandmark& landmark);

// By the extension: .csv or .mrk.json/.json; Error(kBadValue, path) for another. Crash-safe.
void write_detection(const std::filesystem::path& path, const LandmarkDetection& detection);

}  // namespace maxillo::landmarking
