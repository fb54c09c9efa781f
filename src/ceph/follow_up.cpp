#include "ceph/follow_up.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "ceph/landmark_format_support.h"
#include "core/atomic_file.h"
#include "core/error.h"

namespace maxillo::ceph {
namespace {

const TimePointAnalysis* at(const CaseFollowUp& c, const std::string& label) {
  for (const auto& tp : c.time_points)
    if (tp.label == label) return &tp;
  return nullptr;
}

}  // namespace

std::vector<CohortCase> parse_cohort_csv(std::string_view text, const std::string& source) {
  using namespace landmark_format;
  Collector numbers(source);
  std::vector<CohortCase> cohort;
  std::map<std::pair<std::string, std::string>, Collector> collectors;
  std::map<std::pair<std::string, std::string>, std::string> dates;
  std::vector<std::pair<std::string, std::string>> order;
  size_t line_number = 0;
  bool header_seen = false;
  for (size_t start = 0; start <= text.size();) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    auto line = trim(text.substr(start, end - start));
    start = end + 1;
    ++line_number;
    if (line.empty() || line.front() == '#') continue;
    auto fields = split(line, ',');
    auto where = line_name(line_number);
    if (!header_seen) {
      if (fields.size() != 7 || lower(fields[0]) != "case" || lower(fields[3]) != "label")
        numbers.fail(where, "header must be case,time_point,date,label,x,y,z");
      header_seen = true;
      continue;
    }
    if (fields.size() != 7) numbers.fail(where, "expected 7 columns (case,time_point,date,label,x,y,z)");
    if (fields[0].empty() || fields[1].empty()) numbers.fail(where, "empty case or time point");
    std::pair key{std::string(fields[0]), std::string(fields[1])};
    Eigen::Vector3d p(numbers.parse_number(fields[4], "x", where), numbers.parse_number(fields[5], "y", where),
                      numbers.parse_number(fields[6], "z", where));
    auto [it, inserted] = collectors.try_emplace(key, Collector(source));
    if (inserted) {
      order.push_back(key);
      dates[key] = std::string(fields[2]);
    } else if (dates[key] != fields[2]) {
      numbers.fail(where, "date differs from earlier rows of " + key.first + " / " + key.second);
    }
    it->second.add(std::string(fields[3]), p, where);
    if (end == text.size()) break;
  }
  if (!header_seen) numbers.fail("line 1", "empty cohort file");
  for (const auto& key : order) {
    auto found = std::find_if(cohort.begin(), cohort.end(), [&](const CohortCase& c) { return c.name == key.first; });
    if (found == cohort.end()) {
      cohort.push_back({key.first, {}});
      found = cohort.end() - 1;
    }
    found->time_points.push_back({key.second, dates[key], collectors.at(key).take()});
  }
  return cohort;
}

std::vector<CohortCase> read_cohort_csv(const std::filesystem::path& path) {
  auto bytes = read_file(path);
  return parse_cohort_csv(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), path.string());
}

CaseFollowUp make_follow_up(std::string name, std::vector<TimePointAnalysis> time_points) {
  std::stable_sort(time_points.begin(), time_points.end(), [](const auto& a, const auto& b) {
    if (a.date.empty() || b.date.empty()) return !a.date.empty() && b.date.empty();
    return a.date < b.date;
  });
  return {std::move(name), std::move(time_points)};
}

std::vector<ChangeRow> cohort_changes(const std::vector<CaseFollowUp>& cohort, const std::string& from,
                                      const std::string& to, const std::vector<std::string>& ids) {
  std::vector<ChangeRow> rows;
  for (const auto& id : ids) {
    ChangeRow row;
    row.id = id;
    std::vector<double> changes;
    for (const auto& c : cohort) {
      const auto *a = at(c, from), *b = at(c, to);
      if (!a || !b) continue;
      if (const auto* m = a->analysis.find(id)) row.unit = m->unit;
      auto va = a->analysis.value(id), vb = b->analysis.value(id);
      if (va && vb) changes.push_back(*vb - *va);
    }
    row.n = static_cast<int>(changes.size());
    if (row.n > 0) {
      double sum = 0;
      for (double d : changes) sum += d;
      row.mean = sum / row.n;
    }
    if (row.n > 1) {
      double squares = 0;
      for (double d : changes) squares += (d - *row.mean) * (d - *row.mean);
      row.sd = std::sqrt(squares / (row.n - 1));
    }
    rows.push_back(row);
  }
  return rows;
}

std::string format_mean_sd(const ChangeRow& row, int decimals) {
  if (!row.mean) return "n/a";
  char buffer[64];
  double mean = std::abs(*row.mean) < 0.5 * std::pow(10, -decimals) ? 0.0 : *row.mean;  // no "-0.0"
  if (!row.sd) {
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, mean);
  } else {
    std::snprintf(buffer, sizeof buffer, "%.*f \u00b1 %.*f", decimals, mean, decimals, *row.sd);
  }
  return buffer;
}

}  // namespace maxillo::ceph
