#pragma once
// Time points on a month axis, for the follow-up over time (the source's Fig. 10: the Wits
// appraisal of each patient before distraction, at its end, then 6, 12, 14, ... months after).
//
// Convention: months = days / 30.4375 (the mean Gregorian month, 365.25 / 12 days), so 2001-03-15
// to 2001-09-15 (184 days) is 6.05 months and one year is 12.0 months. Dates are "YYYY-MM-DD"
// in the proleptic Gregorian calendar.
//
// Origin (month 0) of a case, as the source counts: its end-of-distraction time point (label
// "post", "post-distraction", "end of distraction", "end-of-distraction" or "EOD", any case)
// when that one is dated; else its first dated time point. Earlier time points (pre-operative)
// then have negative months.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ceph/follow_up.h"

namespace maxillo::ceph {

inline constexpr double kDaysPerMonth = 365.25 / 12;  // 30.4375

// Days since 1970-01-01 of a valid "YYYY-MM-DD" date (month 1-12, day within that month,
// leap years included); nullopt for anything else.
std::optional<std::int64_t> days_since_epoch(std::string_view iso_date);

// Months from `from` to `to`, negative when `to` is earlier. Error(kBadValue, date) for a date
// that is not a valid "YYYY-MM-DD".
double months_between(const std::string& from, const std::string& to);

bool is_end_of_distraction_label(std::string_view label);

enum class MonthsOrigin { kEndOfDistraction, kFirstTimePoint };

// One measurement of one case over months: its dated time points having a value, by date.
struct MeasurementOverMonths {
  std::string name;  // the case
  MonthsOrigin origin = MonthsOrigin::kFirstTimePoint;
  std::vector<std::string> labels;  // the time points used
  std::vector<double> months;
  std::vector<double> values;
};

// Per case (in cohort order) the measurement `id` over months; undated time points and those
// without the value are left out, so a case may have no point. Error(kBadValue) for a malformed date.
MeasurementOverMonths measurement_over_months(const CaseFollowUp& follow_up, const std::string& id);
std::vector<MeasurementOverMonths> measurement_over_months(const std::vector<CaseFollowUp>& cohort,
                                                           const std::string& id);

}  // namespace maxillo::ceph
