// Listing and resolving: read-only queries over the index.
#include <algorithm>
#include <charconv>
#include <tuple>

#include "archive/archive_sql.h"
#include "archive/archive_state.h"

namespace maxillo {
namespace {

std::optional<int> optional_int(const db::Statement& row, int column) {
  if (row.is_null(column)) return std::nullopt;
  return static_cast<int>(row.integer(column));
}
std::optional<double> optional_real(const db::Statement& row, int column) {
  if (row.is_null(column)) return std::nullopt;
  return row.real(column);
}

PatientRecord patient_from(const db::Statement& row) {
  return {row.integer(0), row.text(1), row.text(2), row.text(3), row.text(4), row.integer(5)};
}
StudyRecord study_from(const db::Statement& row) {
  return {row.integer(0), row.integer(1), row.text(2), row.text(3),
          row.text(4),    row.text(5),    row.text(6), row.integer(7)};
}
InstanceRecord instance_from(const db::Statement& r) {
  return InstanceRecord{r.integer(0), r.integer(1), r.text(2), r.text(3),    optional_int(r, 4), r.text(5),
                        r.text(6),    r.text(7),    r.text(8), r.integer(9), r.text(10),         r.text(11)};
}

SeriesRecord series_from(const db::Statement& row) {
  return {
      row.integer(0),         row.integer(1),       row.text(2),          row.text(3),           row.text(4),
      optional_int(row, 5),   optional_int(row, 6), optional_int(row, 7), optional_real(row, 8), optional_real(row, 9),
      optional_real(row, 10), row.integer(11)};
}

template <typename Record, typename Convert>
std::vector<Record> all_rows(db::Connection& db, const std::string& sql, Convert convert,
                             std::optional<int64_t> parameter = std::nullopt) {
  db::Statement query(db, sql);
  if (parameter) query.bind(1, *parameter);
  std::vector<Record> rows;
  while (query.step()) rows.push_back(convert(query));
  return rows;
}

std::optional<int64_t> id_of(db::Connection& db, const char* sql, std::string_view key) {
  db::Statement query(db, sql);
  query.bind(1, key);
  if (query.step()) return query.integer(0);
  return std::nullopt;
}

bool row_exists(db::Connection& db, const char* sql, int64_t id) {
  db::Statement query(db, sql);
  query.bind(1, id);
  return query.step();
}

std::optional<int64_t> as_number(std::string_view text) {
  int64_t value = 0;
  auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (status != std::errc() || end != text.data() + text.size() || value <= 0) return std::nullopt;
  return value;
}

}  // namespace

std::vector<PatientRecord> Archive::patients() const {
  return all_rows<PatientRecord>(state_->db, std::string(sql::kPatients) + " ORDER BY p.id", patient_from);
}

std::vector<StudyRecord> Archive::studies(std::optional<int64_t> patient) const {
  std::string query = sql::kStudies;
  query += patient ? " WHERE s.patient = ?1 ORDER BY s.date, s.time, s.id" : " ORDER BY s.id";
  return all_rows<StudyRecord>(state_->db, query, study_from, patient);
}

std::vector<SeriesRecord> Archive::series(std::optional<int64_t> study) const {
  std::string query = sql::kSeries;
  query += study ? " WHERE x.study = ?1 ORDER BY x.number IS NULL, x.number, x.id" : " ORDER BY x.id";
  return all_rows<SeriesRecord>(state_->db, query, series_from, study);
}

std::optional<PatientRecord> Archive::patient(int64_t id) const {
  auto rows = all_rows<PatientRecord>(state_->db, std::string(sql::kPatients) + " WHERE p.id = ?1", patient_from, id);
  return rows.empty() ? std::nullopt : std::optional(rows.front());
}

std::optional<StudyRecord> Archive::study(int64_t id) const {
  auto rows = all_rows<StudyRecord>(state_->db, std::string(sql::kStudies) + " WHERE s.id = ?1", study_from, id);
  return rows.empty() ? std::nullopt : std::optional(rows.front());
}

std::optional<SeriesRecord> Archive::series_by_id(int64_t id) const {
  auto rows = all_rows<SeriesRecord>(state_->db, std::string(sql::kSeries) + " WHERE x.id = ?1", series_from, id);
  return rows.empty() ? std::nullopt : std::optional(rows.front());
}

std::map<int64_t, CaseContents> read_case_contents(db::Connection& db, const std::vector<int64_t>& case_ids) {
  std::map<int64_t, CaseContents> found;
  db::for_each_row_with_ids(db, sql::kCasesWithPatientsIn, ")", case_ids, [&](const db::Statement& row) {
    auto& contents = found[row.integer(8)];
    contents.patient = patient_from(row);
    contents.record = CaseRecord{row.integer(8), contents.patient.id, row.text(6), row.text(7)};
  });
  db::for_each_row_with_ids(db, sql::kSeriesOfCasesIn, ")", case_ids, [&](const db::Statement& row) {
    if (auto c = found.find(row.integer(13)); c != found.end())
      c->second.series.push_back({series_from(row), row.text(12)});
  });
  db::for_each_row_with_ids(db, sql::kStudiesOfCasesIn, ")", case_ids, [&](const db::Statement& row) {
    if (auto c = found.find(row.integer(8)); c != found.end()) c->second.studies.push_back(study_from(row));
  });
  return found;
}

std::vector<InstanceRecord> Archive::instances(int64_t series) const {
  return all_rows<InstanceRecord>(state_->db, std::string(sql::kInstanceColumns) + sql::kOfSeriesInOrder, instance_from,
                                  series);
}

std::optional<InstanceRecord> Archive::instance(int64_t id) const {
  auto rows =
      all_rows<InstanceRecord>(state_->db, std::string(sql::kInstanceColumns) + sql::kWithId, instance_from, id);
  return rows.empty() ? std::nullopt : std::optional(rows.front());
}

std::vector<CaseRecord> Archive::cases() const {
  return all_rows<CaseRecord>(state_->db, std::string(sql::kCases) + " ORDER BY id", [](const db::Statement& r) {
    return CaseRecord{r.integer(0), r.integer(1), r.text(2), r.text(3)};
  });
}

std::vector<IdentityFlag> Archive::identity_flags() const {
  return all_rows<IdentityFlag>(state_->db, sql::kIdentityFlags, [](const db::Statement& r) {
    return IdentityFlag{r.integer(0), r.integer(1), r.text(2), r.text(3), r.text(4), r.text(5), r.text(6), r.text(7)};
  });
}

std::vector<std::string> Archive::series_object_hashes(int64_t series) const {
  return series_object_hashes(std::vector<int64_t>{series}).at(series);
}

std::map<int64_t, std::vector<std::string>> Archive::series_object_hashes(const std::vector<int64_t>& series) const {
  // In kOfSeriesInOrder's order: by instance number, numberless instances last, then by id.
  struct Member {
    std::optional<int> number;
    int64_t id;
    std::string object;
    bool operator<(const Member& other) const {
      return std::make_tuple(!number, number.value_or(0), id) <
             std::make_tuple(!other.number, other.number.value_or(0), other.id);
    }
  };
  std::map<int64_t, std::vector<Member>> members;
  for (int64_t id : series) members[id];
  db::for_each_row_with_ids(state_->db, sql::kObjectsOfSeriesIn, ")", series, [&](const db::Statement& row) {
    members[row.integer(0)].push_back({optional_int(row, 2), row.integer(3), row.text(1)});
  });
  std::map<int64_t, std::vector<std::string>> hashes;
  for (auto& [id, of_series] : members) {
    std::sort(of_series.begin(), of_series.end());
    auto& names = hashes[id];
    for (auto& member : of_series) names.push_back(std::move(member.object));
  }
  return hashes;
}

std::vector<std::filesystem::path> Archive::series_instance_files(int64_t series) const {
  std::vector<std::filesystem::path> files;
  for (const auto& sha : series_object_hashes(series)) files.push_back(state_->objects.path_of(sha));
  return files;
}

namespace {

// "case:3", "series:12"...: an archive id with its kind spelt out, for when bare numbers of
// different kinds collide.
std::optional<ResolvedItem> typed_id(std::string_view text) {
  constexpr std::pair<std::string_view, ItemKind> kPrefixes[] = {{"patient:", ItemKind::Patient},
                                                                 {"study:", ItemKind::Study},
                                                                 {"series:", ItemKind::Series},
                                                                 {"instance:", ItemKind::Instance},
                                                                 {"case:", ItemKind::Case}};
  for (const auto& [prefix, kind] : kPrefixes)
    if (text.starts_with(prefix))
      if (auto number = as_number(text.substr(prefix.size()))) return ResolvedItem{kind, *number};
  return std::nullopt;
}

}  // namespace

ResolvedItem Archive::resolve(std::string_view text) const {
  auto& db = state_->db;
  if (auto typed = typed_id(text)) {
    constexpr ItemKind kinds[] = {ItemKind::Series, ItemKind::Study, ItemKind::Patient, ItemKind::Case};
    for (size_t n = 0; n < std::size(kinds); ++n)
      if (kinds[n] == typed->kind && row_exists(db, sql::kExists[n], typed->id)) return *typed;
    if (typed->kind == ItemKind::Instance && instance(typed->id)) return *typed;
    throw Error(ErrorCode::kNotFound, std::string(text), "no such " + to_string(typed->kind));
  }
  if (auto number = as_number(text)) {
    constexpr ItemKind kinds[] = {ItemKind::Series, ItemKind::Study, ItemKind::Patient, ItemKind::Case};
    for (size_t n = 0; n < std::size(kinds); ++n)
      if (row_exists(db, sql::kExists[n], *number)) return {kinds[n], *number};
  }
  if (auto id = id_of(db, sql::kPatientIdOf, text)) return {ItemKind::Patient, *id};
  if (auto id = id_of(db, sql::kStudyIdOf, text)) return {ItemKind::Study, *id};
  if (auto id = id_of(db, sql::kSeriesIdOf, text)) return {ItemKind::Series, *id};
  if (auto id = id_of(db, sql::kInstanceIdOf, text)) return {ItemKind::Instance, *id};
  throw Error(ErrorCode::kNotFound, std::string(text), "no patient, study, series, instance or case with this ID");
}

int64_t Archive::resolve_series(std::string_view text) const {
  if (auto number = as_number(text); number && row_exists(state_->db, sql::kExists[0], *number)) return *number;
  if (auto id = id_of(state_->db, sql::kSeriesIdOf, text)) return *id;
  throw Error(ErrorCode::kNotFound, std::string(text), "no series with this archive id or Series Instance UID");
}

}  // namespace maxillo
