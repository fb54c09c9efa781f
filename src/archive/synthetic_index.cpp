#include "archive/synthetic_index.h"

#include <cstdio>

#include "archive/archive_sql.h"
#include "archive/archive_state.h"
#include "core/error.h"
#include "core/utc_time.h"

namespace maxillo {
namespace {

// A 64-hex-digit name no real object has (object n of the synthetic archive).
std::string synthetic_sha256(int64_t n) {
  char text[65];
  std::snprintf(text, sizeof text, "%064llx", static_cast<unsigned long long>(n));
  return text;
}

struct Inserts {
  explicit Inserts(db::Connection& db)
      : patient(db, sql::kInsertPatient),
        study(db, sql::kInsertStudy),
        series(db, sql::kInsertSeries),
        case_row(db, sql::kInsertDefaultCase),
        member(db, "INSERT INTO case_series(case_id, series, role) VALUES (?1, ?2, ?3)"),
        object(db, sql::kInsertObject),
        instance(db, sql::kInsertInstance) {}
  db::Statement patient, study, series, case_row, member, object, instance;
};

void add_series(Inserts& in, int64_t patient, int64_t study, int64_t case_id, const char* role, int64_t instances,
                int64_t& next_object, const std::string& now) {
  const std::string uid = "2.25.9" + std::to_string(patient) + "." + (role[1] == 'r' ? "1" : "2");
  in.series.reset().bind(1, study).bind(2, uid).bind(3, "CT").bind(4, role).bind(5, 1).bind(6, 512).bind(7, 512);
  in.series.bind(8, 0.4).bind(9, 0.4).bind(10, 0.4);
  const int64_t series = db::inserted_id(in.series).value();
  in.member.reset().bind(1, case_id).bind(2, series).bind(3, role).run();
  for (int64_t k = 0; k < instances; ++k) {
    const std::string sha = synthetic_sha256(++next_object);
    in.object.reset().bind(1, sha).bind(2, int64_t(524288)).run();
    auto& s = in.instance.reset();
    s.bind(1, series).bind(2, uid + "." + std::to_string(k + 1)).bind(3, "1.2.840.10008.5.1.4.1.1.2");
    s.bind(4, int(k + 1))
        .bind(5, "0\\0\\" + std::to_string(k))
        .bind(6, "1\\0\\0\\0\\1\\0")
        .bind(7, "1.2.840.10008.1.2.1");
    s.bind(8, sha).bind(9, int64_t(524288)).bind(10, "synthetic").bind(11, now);
    s.run();
  }
}

}  // namespace

void fill_synthetic_index(const std::filesystem::path& address, const SyntheticIndexSize& size) {
  if (!Archive::open(address, OpenMode::CreateIfMissing).patients().empty())
    throw Error(ErrorCode::kConflict, address.string(), "not an empty archive");
  const auto connection = connect_index(parse_archive_location(address.string()), sqlite::OpenKind::Existing);
  db::Connection& db = *connection;
  const int64_t per_series = size.instances / (2 * size.patients);
  const std::string now = utc_now();
  int64_t next_object = 0;
  for (int64_t first = 0; first < size.patients; first += 100) {
    db::Transaction transaction(db);
    Inserts in(db);
    for (int64_t p = first; p < std::min(size.patients, first + 100); ++p) {
      char patient_id[24];  // "P" and up to 19 digits of an int64
      std::snprintf(patient_id, sizeof patient_id, "P%06lld", static_cast<long long>(p));
      in.patient.reset().bind(1, patient_id).bind(2, "Synthetic^Patient").bind(3, "19800101").bind(4, "F").bind(5, now);
      const int64_t patient = db::inserted_id(in.patient).value();
      in.study.reset().bind(1, patient).bind(2, "2.25.8" + std::to_string(p)).bind(3, "20250101").bind(4, "");
      in.study.bind(5, "synthetic").bind(6, "");
      const int64_t study = db::inserted_id(in.study).value();
      const int64_t case_id = db::inserted_id(in.case_row.reset().bind(1, patient).bind(2, now)).value();
      add_series(in, patient, study, case_id, "preop", per_series, next_object, now);
      add_series(in, patient, study, case_id, "postop", per_series, next_object, now);
    }
    transaction.commit();
  }
}

}  // namespace maxillo
