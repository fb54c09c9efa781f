// Plain CSV (label,x,y,z in LPS mm) and 3D Slicer's fiducial CSV (.fcsv).
#include <sstream>

#include "ceph/landmark_format_support.h"

namespace maxillo::landmark_format {

LandmarkSet parse_csv(std::string_view text, const std::string& source) {
  Collector out(source);
  std::istringstream in{std::string(text)};
  std::string raw;
  size_t number = 0;
  bool first_content = true;
  bool more_columns = false;  // a header "label,x,y,z,..." announces columns after the point
  while (std::getline(in, raw)) {
    ++number;
    std::string_view line = trim(raw);
    if (line.empty() || line.front() == '#') continue;
    auto fields = split(line, ',');
    if (first_content && lower(line).starts_with("label,x,y,z")) {  // optional header
      first_content = false;
      more_columns = lower(line) != "label,x,y,z";
      continue;
    }
    first_content = false;
    if (more_columns ? fields.size() < 4 : fields.size() != 4)
      out.fail(line_name(number), std::string(more_columns ? "expected at least" : "expected") +
                                      " 4 columns label,x,y,z, found " + std::to_string(fields.size()));
    std::string where = line_name(number);
    // An absent landmark (as `landmarks detect` writes one): a label without coordinates.
    if (more_columns && trim(fields[1]).empty() && trim(fields[2]).empty() && trim(fields[3]).empty()) continue;
    Eigen::Vector3d p(out.parse_number(fields[1], "x", where), out.parse_number(fields[2], "y", where),
                      out.parse_number(fields[3], "z", where));
    out.add(std::string(fields[0]), p, where);
  }
  return out.take();
}

LandmarkSet parse_fcsv(std::string_view text, const std::string& source) {
  Collector out(source);
  Frame frame = Frame::kRas;  // Slicer's default before "# CoordinateSystem" was written
  // Default column order of Slicer's fcsv (version 4.6 and later).
  std::vector<std::string> columns = {"id", "x",   "y",   "z",    "ow",    "ox",   "oy",
                                      "oz", "vis", "sel", "lock", "label", "desc", "associatedNodeID"};
  std::istringstream in{std::string(text)};
  std::string raw;
  size_t number = 0;
  auto column_index = [&](const std::string& name) {
    auto it = std::find(columns.begin(), columns.end(), name);
    return it == columns.end() ? -1 : int(it - columns.begin());
  };
  while (std::getline(in, raw)) {
    ++number;
    std::string_view line = trim(raw);
    if (line.empty()) continue;
    std::string where = line_name(number);
    if (line.front() == '#') {
      std::string_view body = trim(line.substr(1));
      auto equals = body.find('=');
      if (equals == std::string_view::npos) continue;
      std::string key = lower(trim(body.substr(0, equals)));
      std::string_view value = trim(body.substr(equals + 1));
      if (key == "coordinatesystem") {
        std::string v = lower(value);
        if (v == "lps" || v == "1")
          frame = Frame::kLps;
        else if (v == "ras" || v == "0")
          frame = Frame::kRas;
        else
          out.fail(where, "unsupported coordinate system '" + std::string(value) + "' (LPS, RAS, 0 or 1)");
      } else if (key == "columns") {
        columns.clear();
        for (auto c : split(value, ',')) columns.emplace_back(c);
      }
      continue;
    }
    auto fields = split(line, ',');
    int ix = column_index("x"), iy = column_index("y"), iz = column_index("z"), il = column_index("label");
    if (ix < 0 || iy < 0 || iz < 0 || il < 0) out.fail(where, "the columns header lacks x, y, z or label");
    int needed = std::max({ix, iy, iz, il}) + 1;
    if (int(fields.size()) < needed)
      out.fail(where,
               "expected at least " + std::to_string(needed) + " columns, found " + std::to_string(fields.size()));
    Eigen::Vector3d p(out.parse_number(fields[ix], "x", where), out.parse_number(fields[iy], "y", where),
                      out.parse_number(fields[iz], "z", where));
    out.add(std::string(fields[il]), to_lps(p, frame), where);
  }
  return out.take();
}

// CSV and fcsv have no quoting: a label with a comma or line break cannot be written.
void check_plain_labels(const LandmarkSet& set, const char* format) {
  for (const auto& l : set)
    if (l.label.find_first_of(",\r\n") != std::string::npos)
      throw Error(ErrorCode::kBadValue, l.label,
                  std::string("a label with a comma or line break cannot be written as ") + format);
}

std::string format_csv(const LandmarkSet& set) {
  check_plain_labels(set, "CSV");
  std::string text = "label,x,y,z\n";
  for (const auto& l : set)
    text += l.label + "," + number(l.position.x()) + "," + number(l.position.y()) + "," + number(l.position.z()) + "\n";
  return text;
}

std::string format_fcsv(const LandmarkSet& set) {
  check_plain_labels(set, "fcsv");
  std::string text =
      "# Markups fiducial file version = 4.11\n# CoordinateSystem = LPS\n"
      "# columns = id,x,y,z,ow,ox,oy,oz,vis,sel,lock,label,desc,associatedNodeID\n";
  int id = 0;
  for (const auto& l : set)
    text += "vtkMRMLMarkupsFiducialNode_" + std::to_string(id++) + "," + number(l.position.x()) + "," +
            number(l.position.y()) + "," + number(l.position.z()) + ",0,0,0,1,1,1,0," + l.label + ",,\n";
  return text;
}

}  // namespace maxillo::landmark_format
