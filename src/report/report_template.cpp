#include "report/report_template.h"

#include <algorithm>
#include <array>
#include <initializer_list>
#include <set>

#include "core/error.h"
#include "core/json.h"
#include "core/json_input.h"
#include "core/resources.h"

namespace maxillo::report {
namespace {

constexpr std::array<std::string_view, 12> kSectionIds = {"patient",    "summary",     "views",     "contents",
                                                          "planning",   "soft_tissue", "occlusion", "cephalometry",
                                                          "validation", "notes",       "landmarks", "dental"};

class Reader {
 public:
  explicit Reader(std::string_view source) : source_(source) {}

  [[noreturn]] void fail(const std::string& reason) const { throw Error(ErrorCode::kBadTemplate, source_, reason); }

  // Rejects keys of `object` (at `where`) outside `allowed`, naming the first unknown one.
  void only_keys(const Json& object, std::string_view where, std::initializer_list<std::string_view> allowed) const {
    if (!object.is_object()) fail(std::string(where) + " must be an object");
    for (const auto& [key, value] : object.items())
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
        fail("unknown key '" + key + "' in " + std::string(where));
  }

  const Json& member(const Json& object, const std::string& key, std::string_view where) const {
    if (!object.contains(key)) fail("missing key '" + key + "' in " + std::string(where));
    return object.at(key);
  }

  std::string text(const Json& object, const std::string& key, std::string_view where, bool required = true) const {
    if (!object.contains(key)) {
      if (required) fail("missing key '" + key + "' in " + std::string(where));
      return {};
    }
    const Json& value = object.at(key);
    if (!value.is_string()) fail("'" + key + "' in " + std::string(where) + " must be a string");
    return value.get<std::string>();
  }

  double number(const Json& object, const std::string& key, std::string_view where, double min, double max) const {
    const Json& value = member(object, key, where);
    if (!value.is_number()) fail("'" + key + "' in " + std::string(where) + " must be a number");
    const double x = value.get<double>();
    if (x < min || x > max)
      fail("'" + key + "' in " + std::string(where) + " = " + std::to_string(x) + " outside [" + std::to_string(min) +
           ", " + std::to_string(max) + "]");
    return x;
  }

 private:
  std::string source_;
};

void read_page(const Reader& in, const Json& page, ReportTemplate& out) {
  in.only_keys(page, "page", {"size", "orientation", "margins_mm"});
  if (in.text(page, "size", "page") != "A4") in.fail("page size must be \"A4\"");
  if (in.text(page, "orientation", "page") != "portrait") in.fail("page orientation must be \"portrait\"");
  const Json& margins = in.member(page, "margins_mm", "page");
  in.only_keys(margins, "page.margins_mm", {"top", "bottom", "left", "right"});
  out.margin_top_mm = in.number(margins, "top", "page.margins_mm", 15, 60);        // room for the header
  out.margin_bottom_mm = in.number(margins, "bottom", "page.margins_mm", 15, 60);  // and the footer
  out.margin_left_mm = in.number(margins, "left", "page.margins_mm", 5, 60);
  out.margin_right_mm = in.number(margins, "right", "page.margins_mm", 5, 60);
}

void read_fonts(const Reader& in, const Json& fonts, ReportTemplate& out) {
  in.only_keys(fonts, "fonts", {"regular", "bold", "body_size_pt"});
  out.regular_font = in.text(fonts, "regular", "fonts");
  out.bold_font = in.text(fonts, "bold", "fonts");
  out.body_size_pt = in.number(fonts, "body_size_pt", "fonts", 6, 16);
}

void read_sections(const Reader& in, const Json& sections, ReportTemplate& out) {
  if (!sections.is_array() || sections.empty()) in.fail("'sections' must be a non-empty array");
  std::set<std::string> seen;
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const std::string where = "sections[" + std::to_string(i) + "]";
    in.only_keys(sections[i], where, {"id", "heading", "intro"});
    TemplateSection section{in.text(sections[i], "id", where), in.text(sections[i], "heading", where),
                            in.text(sections[i], "intro", where, false)};
    const auto ids = known_section_ids();
    if (std::find(ids.begin(), ids.end(), section.id) == ids.end())
      in.fail("unknown section id '" + section.id + "' in " + where);
    if (!seen.insert(section.id).second) in.fail("section id '" + section.id + "' appears twice");
    out.sections.push_back(std::move(section));
  }
}

}  // namespace

std::span<const std::string_view> known_section_ids() { return kSectionIds; }

ReportTemplate parse_report_template(std::string_view json_text, std::string_view source) {
  const Reader in(source);
  const Json root = parse_json_input(json_text, std::string(source));
  in.only_keys(root, "the template", {"title", "subtitle", "page", "fonts", "footer", "sections"});
  ReportTemplate out;
  out.source = source;
  out.title = in.text(root, "title", "the template");
  out.subtitle = in.text(root, "subtitle", "the template", false);
  out.footer = in.text(root, "footer", "the template");
  read_page(in, in.member(root, "page", "the template"), out);
  read_fonts(in, in.member(root, "fonts", "the template"), out);
  read_sections(in, in.member(root, "sections", "the template"), out);
  return out;
}

ReportTemplate load_report_template(std::string_view resource_path) {
  return parse_report_template(load_resource(resource_path), resource_path);
}

}  // namespace maxillo::report
