#include "report/report_model.h"

#include <cctype>
#include <tuple>

namespace maxillo::report {
namespace {

std::vector<std::string> split(std::string_view text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find(separator, start);
    parts.emplace_back(text.substr(start, end == std::string_view::npos ? text.npos : end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

void append_word(std::string& text, const std::string& word) {
  if (word.empty()) return;
  if (!text.empty()) text += ' ';
  text += word;
}

}  // namespace

std::string format_person_name(std::string_view dicom_pn) {
  const std::string_view alphabetic = dicom_pn.substr(0, dicom_pn.find('='));
  auto parts = split(alphabetic, '^');
  parts.resize(5);
  const auto& [family, given, middle, prefix, suffix] = std::tie(parts[0], parts[1], parts[2], parts[3], parts[4]);
  std::string forenames;
  append_word(forenames, prefix);
  append_word(forenames, given);
  append_word(forenames, middle);
  std::string name = family;
  if (!forenames.empty()) name += name.empty() ? forenames : ", " + forenames;
  if (!suffix.empty()) name += ", " + suffix;
  return name;
}

std::string format_dicom_date(std::string_view dicom_da) {
  if (dicom_da.size() != 8) return std::string(dicom_da);
  for (char c : dicom_da)
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::string(dicom_da);
  return std::string(dicom_da.substr(0, 4)) + "-" + std::string(dicom_da.substr(4, 2)) + "-" +
         std::string(dicom_da.substr(6, 2));
}

std::string format_sex(std::string_view dicom_cs) {
  if (dicom_cs == "M") return "male";
  if (dicom_cs == "F") return "female";
  if (dicom_cs == "O") return "other";
  return std::string(dicom_cs);
}

}  // namespace maxillo::report
