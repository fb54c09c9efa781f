#include "ceph/follow_up_months.h"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "core/error.h"

namespace maxillo::ceph {
namespace {

bool is_leap_year(int year) { return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0; }

int days_in_month(int year, int month) {
  static constexpr int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return month == 2 && is_leap_year(year) ? 29 : kDays[month - 1];
}

std::optional<int> digits(std::string_view text) {
  int value = 0;
  for (char c : text)
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

// Days since 1970-01-01 of a valid civil date (Howard Hinnant's days_from_civil).
std::int64_t days_from_civil(std::int64_t y, unsigned m, unsigned d) {
  y -= m <= 2;
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const unsigned yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<std::int64_t>(doe) - 719468;
}

std::int64_t checked_days(const std::string& date) {
  auto days = days_since_epoch(date);
  if (!days) throw Error(ErrorCode::kBadValue, date.empty() ? "(empty date)" : date, "not a valid YYYY-MM-DD date");
  return *days;
}

std::string lower(std::string_view text) {
  std::string out(text);
  for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

std::optional<std::int64_t> days_since_epoch(std::string_view iso) {
  if (iso.size() != 10 || iso[4] != '-' || iso[7] != '-') return std::nullopt;
  auto year = digits(iso.substr(0, 4));
  auto month = digits(iso.substr(5, 2));
  auto day = digits(iso.substr(8, 2));
  if (!year || !month || !day || *month < 1 || *month > 12 || *day < 1 || *day > days_in_month(*year, *month))
    return std::nullopt;
  return days_from_civil(*year, static_cast<unsigned>(*month), static_cast<unsigned>(*day));
}

double months_between(const std::string& from, const std::string& to) {
  return static_cast<double>(checked_days(to) - checked_days(from)) / kDaysPerMonth;
}

bool is_end_of_distraction_label(std::string_view label) {
  const std::string l = lower(label);
  return l == "post" || l == "post-distraction" || l == "end of distraction" || l == "end-of-distraction" || l == "eod";
}

MeasurementOverMonths measurement_over_months(const CaseFollowUp& follow_up, const std::string& id) {
  MeasurementOverMonths out{follow_up.name, MonthsOrigin::kFirstTimePoint, {}, {}, {}};
  std::vector<const TimePointAnalysis*> dated;
  for (const auto& tp : follow_up.time_points)
    if (!tp.date.empty()) dated.push_back(&tp);
  std::stable_sort(dated.begin(), dated.end(),
                   [](auto* a, auto* b) { return checked_days(a->date) < checked_days(b->date); });
  if (dated.empty()) return out;

  std::string origin = dated.front()->date;
  for (const auto* tp : dated)
    if (is_end_of_distraction_label(tp->label)) {
      origin = tp->date;
      out.origin = MonthsOrigin::kEndOfDistraction;
      break;
    }
  for (const auto* tp : dated)
    if (auto value = tp->analysis.value(id)) {
      out.labels.push_back(tp->label);
      out.months.push_back(months_between(origin, tp->date));
      out.values.push_back(*value);
    }
  return out;
}

std::vector<MeasurementOverMonths> measurement_over_months(const std::vector<CaseFollowUp>& cohort,
                                                           const std::string& id) {
  std::vector<MeasurementOverMonths> out;
  for (const auto& c : cohort) out.push_back(measurement_over_months(c, id));
  return out;
}

}  // namespace maxillo::ceph
