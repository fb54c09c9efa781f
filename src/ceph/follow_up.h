#pragma once
// Long-term follow-up (thesis ch. 5): cephalometric measurements per time point of each patient,
// and per cohort the changes between two time points as mean +- SD with n (the source's Tables
// II and III: pre -> end of distraction, end of distraction -> 6 months).
//
// Cohort CSV (cohort import), header required, one landmark per row, comma separated:
//   case,time_point,date,label,x,y,z
//   P01,pre,2001-03-14,S,812,1004,0
// `case` and `time_point` are free text; `date` is YYYY-MM-DD (or empty); label, x, y, z as in a
// landmark CSV (ceph/landmark_io.h). Rows of one case and time point form one landmark set; the
// coordinates are read as the caller says (LandmarkGeometry, CephalogramAxes), the same for all.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ceph/cephalometric_analysis.h"
#include "ceph/landmark.h"

namespace maxillo::ceph {

struct TimePointSet {
  std::string label;  // "pre", "post", "6M", ...
  std::string date;   // "YYYY-MM-DD" or ""
  LandmarkSet landmarks;
};
struct CohortCase {
  std::string name;
  std::vector<TimePointSet> time_points;  // in file order
};

// Error(kBadValue, path, "line N: ...") on a malformed row (column count, number, duplicate label
// within one case and time point).
std::vector<CohortCase> read_cohort_csv(const std::filesystem::path& path);
std::vector<CohortCase> parse_cohort_csv(std::string_view text, const std::string& source);

struct TimePointAnalysis {
  std::string label;
  std::string date;
  CephalometricAnalysis analysis;
};
struct CaseFollowUp {
  std::string name;
  std::vector<TimePointAnalysis> time_points;  // by date (undated last, in given order)
};

// Orders the analyses by date.
CaseFollowUp make_follow_up(std::string name, std::vector<TimePointAnalysis> time_points);

struct ChangeRow {
  std::string id;  // measurement id
  std::string unit;
  int n = 0;                   // cases having the measurement at both time points
  std::optional<double> mean;  // of (value at `to`) - (value at `from`); nullopt when n = 0
  std::optional<double> sd;    // sample SD (n - 1); nullopt when n < 2
};
// One row per id: the change from time point `from` to `to` over the cases having both.
std::vector<ChangeRow> cohort_changes(const std::vector<CaseFollowUp>& cohort, const std::string& from,
                                      const std::string& to, const std::vector<std::string>& ids);

// "9.9 ± 2.2" (one decimal, as the source's tables), "n/a" without a mean, "9.9" without an SD.
std::string format_mean_sd(const ChangeRow& row, int decimals = 1);

}  // namespace maxillo::ceph
