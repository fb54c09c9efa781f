// 3D Slicer markups JSON (.mrk.json, schema v1.0.3).
#include "ceph/landmark_format_support.h"
#include "ceph/landmark_io.h"
#include "core/json.h"
#include "core/json_input.h"

namespace maxillo::landmark_format {

constexpr const char* kMarkupsSchema =
    "https://raw.githubusercontent.com/slicer/slicer/master/Modules/Loadable/Markups/Resources/Schema/"
    "markups-schema-v1.0.3.json#";

LandmarkSet parse_markups_json(std::string_view text, const std::string& source) {
  Collector out(source);
  const Json document = parse_json_input(text, source);
  if (!document.is_object() || !document.contains("markups") || !document["markups"].is_array())
    out.fail("document", "no \"markups\" array (not a Slicer markups file)");
  size_t markup_number = 0;
  for (const Json& markup : document["markups"]) {
    ++markup_number;
    std::string where_markup = "markup " + std::to_string(markup_number);
    Frame frame = Frame::kLps;
    if (markup.contains("coordinateSystem")) {
      const Json& cs = markup["coordinateSystem"];
      std::string v = cs.is_string() ? cs.get<std::string>() : cs.dump();
      if (v == "LPS")
        frame = Frame::kLps;
      else if (v == "RAS")
        frame = Frame::kRas;
      else
        out.fail(where_markup, "unsupported coordinateSystem '" + v + "' (LPS or RAS)");
    }
    if (!markup.contains("controlPoints")) continue;
    size_t point_number = 0;
    for (const Json& point : markup["controlPoints"]) {
      ++point_number;
      // A point not placed (Slicer's "missing", as `landmarks detect` writes an absent one).
      if (point.contains("positionStatus") && point["positionStatus"] == "missing") continue;
      std::string where = where_markup + ", control point " + std::to_string(point_number);
      if (!point.contains("label") || !point["label"].is_string()) out.fail(where, "missing \"label\"");
      where += " ('" + point["label"].get<std::string>() + "')";
      if (!point.contains("position") || !point["position"].is_array() || point["position"].size() != 3)
        out.fail(where, "missing or malformed \"position\" (3 numbers)");
      Eigen::Vector3d p;
      for (int i = 0; i < 3; ++i) {
        const Json& c = point["position"][size_t(i)];
        if (!c.is_number()) out.fail(where, "position[" + std::to_string(i) + "] is not a number");
        p[i] = c.get<double>();
      }
      out.add(point["label"].get<std::string>(), to_lps(p, frame), where);
    }
  }
  return out.take();
}

std::string format_markups_json(const LandmarkSet& set) {
  std::vector<MarkupPoint> points;
  for (const auto& l : set) points.push_back({l.label, l.position, "", true});
  return format_markup_points(points);
}

}  // namespace maxillo::landmark_format

namespace maxillo {

std::string format_markup_points(const std::vector<MarkupPoint>& points) {
  Json control_points = Json::array();
  int id = 0;
  for (const auto& p : points) {
    const Eigen::Vector3d at = p.position.value_or(Eigen::Vector3d::Zero());
    control_points.push_back({{"id", std::to_string(++id)},
                              {"label", p.label},
                              {"description", p.description},
                              {"associatedNodeID", ""},
                              {"position", {at.x(), at.y(), at.z()}},
                              {"orientation", {-1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 1.0}},
                              {"selected", p.selected},
                              {"locked", false},
                              {"visibility", p.position.has_value()},
                              {"positionStatus", p.position ? "defined" : "missing"}});
  }
  Json markup = {{"type", "Fiducial"},
                 {"coordinateSystem", "LPS"},
                 {"coordinateUnits", "mm"},
                 {"locked", false},
                 {"fixedNumberOfControlPoints", false},
                 {"labelFormat", "%N-%d"},
                 {"lastUsedControlPointNumber", id},
                 {"controlPoints", control_points},
                 {"measurements", Json::array()}};
  Json document = {{"@schema", landmark_format::kMarkupsSchema}, {"markups", Json::array({markup})}};
  return document.dump(4) + "\n";
}

}  // namespace maxillo
