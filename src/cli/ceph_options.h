#pragma once
// Options shared by `maxillo ceph` and `maxillo followup`: how landmark coordinates are read
// (3D LPS or a 2D cephalogram in image axes), the patient's sex for the norms, and the text and
// JSON forms of an analysis.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "ceph/cephalometric_analysis.h"
#include "core/json.h"

namespace maxillo::cli {

struct GeometryOptions {
  LandmarkGeometry geometry = LandmarkGeometry::kAuto;
  double pixel_spacing_mm = 1.0;
  bool image_y_down = false;  // CLI flag; converted by axes()
  bool face_left = false;
  ceph::Sex sex = ceph::Sex::kUnknown;

  CephalogramAxes axes() const {
    return {pixel_spacing_mm, image_y_down ? ImageVerticalAxis::kDown : ImageVerticalAxis::kUp,
            face_left ? FacingDirection::kMinusX : FacingDirection::kPlusX};
  }
};

inline void add_geometry_options(CLI::App& app, GeometryOptions& options) {
  std::map<std::string, LandmarkGeometry> geometries{{"auto", LandmarkGeometry::kAuto},
                                                     {"cephalogram", LandmarkGeometry::kCephalogram},
                                                     {"volume", LandmarkGeometry::kVolumeLps}};
  app.add_option("--geometry", options.geometry,
                 "auto (2D cephalogram when every z is 0), cephalogram (x, y in the image plane) or volume (3D LPS)")
      ->transform(CLI::CheckedTransformer(geometries, CLI::ignore_case));
  app.add_option("--pixel-spacing", options.pixel_spacing_mm, "mm per unit of a cephalogram's x, y (pixels)")
      ->check(CLI::Range(1e-3, 10.0));
  app.add_flag("--image-y-down", options.image_y_down, "cephalogram y grows downwards (image pixel coordinates)");
  app.add_flag("--face-left", options.face_left, "the cephalogram's face looks to -x (default +x)");
  std::map<std::string, ceph::Sex> sexes{
      {"F", ceph::Sex::kFemale}, {"M", ceph::Sex::kMale}, {"unknown", ceph::Sex::kUnknown}};
  app.add_option("--sex", options.sex, "sex for sex-specific norms (Wits): F, M or unknown")
      ->transform(CLI::CheckedTransformer(sexes, CLI::ignore_case));
}

inline std::string fixed(double value, int decimals = 1) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, std::abs(value) < 0.5 * std::pow(10, -decimals) ? 0.0 : value);
  return buffer;
}

inline Json analysis_json(const ceph::CephalometricAnalysis& analysis) {
  Json measurements = Json::array();
  for (const auto& m : analysis.measurements) {
    Json j{{"id", m.id}, {"name", m.name}, {"unit", m.unit}, {"value", nullptr}};
    if (m.value)
      j["value"] = *m.value;
    else
      j["not_available"] = m.not_available_reason;
    if (m.norm) {
      j["norm"] = {{"mean", m.norm->mean}, {"sd", m.norm->sd}, {"source", m.norm->source}};
      if (m.value) j["deviation"] = std::string(ceph::deviation_name(m.deviation));
    }
    if (!m.note.empty()) j["note"] = m.note;
    measurements.push_back(j);
  }
  return Json{{"frame", analysis.frame}, {"measurements", measurements}};
}

inline void print_analysis(const ceph::CephalometricAnalysis& analysis) {
  std::printf("frame: %s; nasion frame X = SN - 6 deg (+ anterior), Y perpendicular (+ inferior)\n",
              analysis.frame.c_str());
  for (const auto& m : analysis.measurements) {
    std::string norm = m.norm ? fixed(m.norm->mean) + " ± " + fixed(m.norm->sd, 2) : "";
    if (m.value)
      std::printf("%-7s %8s %-3s  %-14s %-12s %s\n", m.id.c_str(), fixed(*m.value, 2).c_str(), m.unit.c_str(),
                  norm.c_str(), std::string(ceph::deviation_name(m.deviation)).c_str(), m.note.c_str());
    else
      std::printf("%-7s %8s %-3s  %-14s not available: %s\n", m.id.c_str(), "-", m.unit.c_str(), norm.c_str(),
                  m.not_available_reason.c_str());
  }
}

}  // namespace maxillo::cli
