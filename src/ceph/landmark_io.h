#pragma once
// Landmark files: 3D Slicer markups JSON (.mrk.json), Slicer fiducial CSV (.fcsv) and plain CSV
// (label,x,y,z). The format is chosen by the file name's extension; any other is rejected.
//
// Frames: maxillo works in LPS. We always write LPS ("coordinateSystem": "LPS" in markups JSON,
// "# CoordinateSystem = LPS" in .fcsv; plain CSV is LPS by definition). On reading, RAS files
// (markups "RAS", fcsv "RAS" or legacy "0") are converted: LPS = (-R, -A, S). Legacy fcsv "1" is
// LPS. Missing declarations mean LPS for markups JSON (schema default) and RAS for .fcsv
// (Slicer's default before 4.11).
//
// Errors: Error(kBadValue, path, reason) where the reason names the line (CSV, fcsv, JSON syntax)
// or the control point (JSON content): missing column, non-numeric coordinate, duplicate label,
// empty label, unknown coordinate system. Unreadable files: Error(kFileNotFound/...).
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ceph/landmark.h"

namespace maxillo {

enum class LandmarkFormat { kSlicerMarkupsJson, kSlicerFcsv, kCsv };

// .mrk.json (also any .json), .fcsv, .csv (case-insensitive); else Error(kBadValue, path).
LandmarkFormat landmark_format_for(const std::filesystem::path& path);

LandmarkSet read_landmarks(const std::filesystem::path& path);
// Crash-safe write (temporary file + rename); Error(kWriteFailed) on failure.
void write_landmarks(const std::filesystem::path& path, const LandmarkSet& landmarks);

// A control point of a 3D Slicer markups file: a position, or none ("missing", as an absent
// landmark is written), and a description shown beside it.
struct MarkupPoint {
  std::string label;
  std::optional<Eigen::Vector3d> position;
  std::string description;
  bool selected = true;
};
// The markups document (.mrk.json, LPS) of these points.
std::string format_markup_points(const std::vector<MarkupPoint>& points);

// The same on text; source_name only labels errors.
LandmarkSet parse_landmarks(std::string_view text, LandmarkFormat format, const std::string& source_name);
std::string format_landmarks(const LandmarkSet& landmarks, LandmarkFormat format);

}  // namespace maxillo
