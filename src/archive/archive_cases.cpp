// Cases: the unit of work. One "default" case per patient is made at first import.
#include <algorithm>
#include <charconv>
#include <tuple>

#include "archive/archive_sql.h"
#include "archive/archive_state.h"
#include "archive/journalled_transaction.h"

namespace maxillo {

std::optional<CaseRecord> Archive::case_of_patient(int64_t patient, std::string_view label) const {
  db::Statement query(state_->db, std::string(sql::kCases) + " WHERE patient = ?1 AND label = ?2");
  query.bind(1, patient).bind(2, label);
  if (!query.step()) return std::nullopt;
  return CaseRecord{query.integer(0), query.integer(1), query.text(2), query.text(3)};
}

int64_t Archive::resolve_case(std::string_view text) const {
  if (text.starts_with("case:")) {
    auto item = resolve(text);  // typed: must be a case, or NotFound
    return item.id;
  }
  int64_t number = 0;
  auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (status == std::errc() && end == text.data() + text.size()) {
    db::Statement query(state_->db, sql::kExists[3]);
    query.bind(1, number);
    if (query.step()) return number;
  }
  db::Statement patient(state_->db, sql::kPatientIdOf);
  patient.bind(1, text);
  if (patient.step()) {
    if (auto found = case_of_patient(patient.integer(0))) return found->id;
    // No default case (e.g. a cohort's image-less case): the patient's only case, if it has one.
    std::vector<int64_t> cases;
    for (const auto& c : this->cases())
      if (c.patient == patient.integer(0)) cases.push_back(c.id);
    if (cases.size() == 1) return cases.front();
  }
  throw Error(ErrorCode::kNotFound, std::string(text), "no case with this id and no patient with this Patient ID");
}

namespace {

// Studies by date and time; series by their study's place in that order, then by number and id.
void sort_contents(CaseContents& contents) {
  std::sort(contents.studies.begin(), contents.studies.end(), [](const StudyRecord& a, const StudyRecord& b) {
    return std::tie(a.date, a.time, a.id) < std::tie(b.date, b.time, b.id);
  });
  auto study_rank = [&](int64_t study) {
    return std::find_if(contents.studies.begin(), contents.studies.end(), [&](auto& s) { return s.id == study; }) -
           contents.studies.begin();
  };
  std::sort(contents.series.begin(), contents.series.end(), [&](const CaseSeries& a, const CaseSeries& b) {
    return std::make_tuple(study_rank(a.series.study), a.series.number.value_or(1 << 30), a.series.id) <
           std::make_tuple(study_rank(b.series.study), b.series.number.value_or(1 << 30), b.series.id);
  });
}

}  // namespace

std::map<int64_t, CaseContents> Archive::case_contents(const std::vector<int64_t>& case_ids) const {
  auto found = read_case_contents(state_->db, case_ids);
  for (auto& [id, contents] : found) sort_contents(contents);
  return found;
}

CaseContents Archive::case_contents(int64_t case_id) const {
  auto found = case_contents(std::vector<int64_t>{case_id});
  if (found.empty()) throw Error(ErrorCode::kNotFound, std::to_string(case_id), "no such case");
  return std::move(found.begin()->second);
}

void Archive::set_series_role(int64_t case_id, int64_t series, std::string_view role) {
  static constexpr std::string_view kRoles[] = {"preop", "postop", "follow-up", "report", "unassigned"};
  if (std::find(std::begin(kRoles), std::end(kRoles), role) == std::end(kRoles))
    throw Error(ErrorCode::kBadValue, std::string(role), "unknown role (preop, postop, follow-up, report, unassigned)");
  StoreLock lock(*state_, LockKind::Shared);  // verify and rebuild see no half-done change
  JournalledTransaction transaction(state_->db, state_->journal, "role");
  db::Statement update(state_->db, sql::kSetSeriesRole);
  if (update.bind(1, case_id).bind(2, series).bind(3, role).run() != 1)
    throw Error(ErrorCode::kNotFound, std::to_string(series), "series is not part of case " + std::to_string(case_id));
  transaction.written("case_series", "case_id = ?1 AND series = ?2", {case_id, series});
  transaction.commit();
}

}  // namespace maxillo
