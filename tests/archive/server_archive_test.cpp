// What only an archive on a PostgreSQL server has: its address, its schema table, nodes that
// start at once, a database lost beside a shared object folder, and the store lock that other
// nodes see. Tests that need the server skip without one (scripts/test-postgres starts it).
#include <gtest/gtest.h>
#include <libpq-fe.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <regex>
#include <thread>

#include "archive/archive.h"
#include "archive/index_comparison.h"
#include "archive/postgres.h"
#include "archive_fixture.h"

namespace maxillo {
namespace {

using testing::quiet;
using testing::TemporaryFolder;

#define REQUIRE_SERVER() \
  if (!testing::on_server()) GTEST_SKIP() << "no test PostgreSQL server (MAXILLO_TEST_POSTGRES)"

std::string database_of(const std::filesystem::path& address) {
  std::string text = address.string();
  return text.substr(0, text.find('?'));
}

// A second client of the database, as another node or an administrator would be.
class Client {
 public:
  explicit Client(const std::filesystem::path& address) : connection_(PQconnectdb(database_of(address).c_str())) {
    EXPECT_EQ(PQstatus(connection_), CONNECTION_OK) << PQerrorMessage(connection_);
  }
  ~Client() { PQfinish(connection_); }
  void run(const std::string& sql) {
    PGresult* result = PQexec(connection_, sql.c_str());
    EXPECT_TRUE(PQresultStatus(result) == PGRES_COMMAND_OK || PQresultStatus(result) == PGRES_TUPLES_OK)
        << sql << ": " << PQerrorMessage(connection_);
    PQclear(result);
  }
  std::string value(const std::string& sql) {
    PGresult* result = PQexec(connection_, sql.c_str());
    std::string text = PQntuples(result) > 0 ? PQgetvalue(result, 0, 0) : "";
    PQclear(result);
    return text;
  }

 private:
  PGconn* connection_;
};

ErrorCode open_error(const std::filesystem::path& address, OpenMode mode = OpenMode::Existing) {
  try {
    Archive::open(address, mode);
  } catch (const Error& e) {
    return e.code();
  }
  return ErrorCode::kProcessing;
}

TEST(ServerArchive, AnUnreachableServerIsNamedInTheArchiveRange) {
  TemporaryFolder folder;
  const std::string address = "postgresql://maxillo:secret@127.0.0.1:1/archive?objects=" + folder.path().string();
  try {
    Archive::open(address);
    FAIL() << "opened";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kArchiveUnreachable);
    EXPECT_EQ(exit_code_for(e.code()), 48);
    EXPECT_NE(e.subject().find("127.0.0.1"), std::string::npos) << e.subject();
    EXPECT_EQ(std::string(e.what()).find("secret"), std::string::npos);
    EXPECT_EQ(e.subject().find("secret"), std::string::npos) << e.subject();
  }
}

// Issue 29, fault 11: a login the server refuses was "unreachable" (48).
TEST(ServerArchive, ALoginTheServerRefusesHasItsOwnCodeNotUnreachable) {
  if (!testing::on_server()) GTEST_SKIP() << "no test PostgreSQL server";
  TemporaryFolder folder;
  const std::string server = testing::test_postgres_server();  // postgresql://postgres@127.0.0.1:PORT/
  const std::string unknown_role = std::regex_replace(server, std::regex("postgres@"), "no_such_role@") + "postgres";
  for (const std::string& address : {unknown_role, server + "no_such_database"}) {
    try {
      Archive::open(address + "?objects=" + folder.path().string());
      ADD_FAILURE() << address << " opened";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::kArchiveLoginRefused) << e.what();
      EXPECT_EQ(exit_code_for(e.code()), 50);
      EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
    }
  }
}

TEST(ServerArchive, AMissingSharedObjectFolderIsRefusedBeforeAnythingIsWritten) {
  TemporaryFolder folder;
  EXPECT_EQ(open_error("postgresql://h/db?objects=" + (folder / "absent").string(), OpenMode::CreateIfMissing),
            ErrorCode::kBadArchiveAddress);
  EXPECT_FALSE(std::filesystem::exists(folder / "absent"));
}

// A server archive of one small series in folder/objects whose database is then lost: the
// address of the same shared folder with a new, empty database (and that database's).
struct LostDatabase {
  std::string database, address;
};
LostDatabase archive_whose_database_is_lost(const TemporaryFolder& folder) {
  testing::write_series(folder / "in", 3);
  Archive archive = Archive::open(testing::archive_at(folder / "objects"), OpenMode::CreateIfMissing);
  archive.import_paths({folder / "in"}, quiet());
  LostDatabase lost;
  lost.database = testing::new_test_database();
  lost.address = lost.database + "?objects=" + (folder / "objects").string();
  return lost;
}

TEST(ServerArchive, ALostDatabaseBesideStoredObjectsIsRefusedAndNeverRecreatedEmpty) {
  REQUIRE_SERVER();
  TemporaryFolder folder;
  const std::string lost = archive_whose_database_is_lost(folder).address;
  EXPECT_EQ(open_error(lost, OpenMode::CreateIfMissing), ErrorCode::kIndexDamaged);
  Client client(lost);
  EXPECT_EQ(client.value("SELECT COUNT(*) FROM pg_tables WHERE schemaname = 'public'"), "0");
}

// Issue 29, fault 2 on the server engine: while `archive rebuild-index` fills the new database
// (holding the store lock alone), a command that opens it is told to wait, not that the index
// is lost; once the lock is free it is refused as before.
TEST(ServerArchive, AnOpenDuringARebuildIsToldToWait) {
  REQUIRE_SERVER();
  TemporaryFolder folder;
  const auto [database, address] = archive_whose_database_is_lost(folder);
  {
    postgres::Connection rebuild(database);
    rebuild.lock(postgres::kStoreLockKey, false);  // as rebuild-index holds it
    try {
      Archive::open(address);
      ADD_FAILURE() << "opened during the rebuild";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::kArchiveBusy);
      EXPECT_NE(std::string(e.what()).find("being rebuilt"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(open_error(address), ErrorCode::kIndexDamaged);
}

TEST(ServerArchive, ALostDatabaseIsRebuiltFromTheSharedFolderRowForRow) {
  REQUIRE_SERVER();
  TemporaryFolder folder;
  testing::write_series(folder / "a", 4, "P1", "Doe^Jane");
  testing::write_series(folder / "b", 3, "P1", "Roe^Richard");
  const auto shared = folder / "objects";
  const auto original = testing::archive_at(shared);
  {
    Archive archive = Archive::open(original, OpenMode::CreateIfMissing);
    archive.import_paths({folder / "a", folder / "b"}, quiet());
    archive.set_series_role(1, 2, "postop");
    NewArtefact artefact{archive.ensure_case("C-1", "cohort"),
                         "report",
                         archive.store_object("a report"),
                         "application/pdf",
                         "inputs",
                         R"({"pages": 2})"};
    archive.add_artefact(artefact);
  }
  // The database is lost; the administrator makes a new, empty one for the same folder.
  const std::string replacement = testing::new_test_database() + "?objects=" + shared.string();
  RebuildReport report = Archive::rebuild_index(replacement, RebuildOptions{false, ProgressDisplay::Never});
  EXPECT_TRUE(report.journal_problems.empty());
  EXPECT_TRUE(report.disagreements.empty());
  EXPECT_EQ(report.instances_checked, 7u);
  EXPECT_EQ(report.rows.at("identity_flags"), 1);
  Archive rebuilt = Archive::open(replacement);
  Archive before = Archive::open(original);
  EXPECT_EQ(rebuilt.patients().size(), before.patients().size());
  EXPECT_EQ(rebuilt.case_contents(1).series[1].role, before.case_contents(1).series[1].role);
  EXPECT_EQ(rebuilt.artefacts(2).size(), 1u);
  EXPECT_TRUE(rebuilt.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
  // Every table, row for row, ids included.
  postgres::Connection lost(database_of(original)), replaced(database_of(replacement));
  for (const auto& difference : compare_indexes(lost, replaced)) ADD_FAILURE() << difference.describe();
  // A database that holds an index is never rebuilt over, forced or not.
  try {
    Archive::rebuild_index(replacement, RebuildOptions{true, ProgressDisplay::Never});
    FAIL() << "rebuilt over an index";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kConflict);
  }
}

TEST(ServerArchive, NodesStartingAtOnceMigrateOnceAndAllWork) {
  REQUIRE_SERVER();
  TemporaryFolder folder;
  const auto address = testing::archive_at(folder / "objects");
  std::atomic<int> opened = 0;
  std::vector<std::thread> nodes;
  for (int node = 0; node < 4; ++node)
    nodes.emplace_back([&] {
      Archive archive = Archive::open(address, OpenMode::CreateIfMissing);
      if (archive.schema_version() == Archive::newest_schema_version()) ++opened;
    });
  for (auto& node : nodes) node.join();
  EXPECT_EQ(opened, 4);
  Client client(address);
  EXPECT_EQ(client.value("SELECT version FROM maxillo_schema"), std::to_string(Archive::newest_schema_version()));
  EXPECT_EQ(client.value("SELECT COUNT(*) FROM maxillo_schema"), "1");
}

TEST(ServerArchive, ASchemaNewerThanTheProgramIsRefused) {
  REQUIRE_SERVER();
  TemporaryFolder folder;
  const auto address = testing::archive_at(folder / "objects");
  { Archive::open(address, OpenMode::CreateIfMissing); }
  Client(address).run("UPDATE maxillo_schema SET version = " + std::to_string(Archive::newest_schema_version() + 1));
  EXPECT_EQ(open_error(address), ErrorCode::kSchemaTooNew);
}

TEST(ServerArchive, RowsEditedBehindTheArchivesBackAreFoundByVerifyAndRepairRefuses) {
  REQUIRE_SERVER();
  TemporaryFolder folder;
  testing::write_series(folder / "in", 3);
  const auto address = testing::archive_at(folder / "objects");
  Archive archive = Archive::open(address, OpenMode::CreateIfMissing);
  archive.import_paths({folder / "in"}, quiet());
  ASSERT_TRUE(archive.verify(RepairMode::ReportOnly, ProgressDisplay::Never).consistent());
  Client(address).run("UPDATE patients SET name = 'Edited^Behind'");
  VerifyReport report = archive.verify(RepairMode::Repair, ProgressDisplay::Never);
  ASSERT_FALSE(report.journal_differences.empty());
  EXPECT_NE(report.journal_differences[0].find("patients"), std::string::npos) << report.journal_differences[0];
  EXPECT_FALSE(report.repair_refused.empty());
}

TEST(ServerArchive, RepairLeavesStraysYoungerThanTheGracePeriod) {
  REQUIRE_SERVER();
  TemporaryFolder folder;
  testing::write_series(folder / "in", 2);
  Archive archive = Archive::open(testing::archive_at(folder / "objects"), OpenMode::CreateIfMissing);
  archive.import_paths({folder / "in"}, quiet());
  // An object another node has just written and not yet committed a row for.
  const auto stray = archive.object_path(std::string(64, 'a'));
  std::filesystem::create_directories(stray.parent_path());
  std::ofstream(stray) << "being imported elsewhere";
  VerifyReport waited = archive.verify(RepairMode::Repair, ProgressDisplay::Never);
  EXPECT_EQ(waited.orphans.size(), 1u);
  EXPECT_EQ(waited.within_grace, 1u);
  EXPECT_EQ(waited.quarantined, 0u);
  EXPECT_TRUE(std::filesystem::exists(stray));
  // Once older than the grace period (here: none), it is set aside.
  VerifyReport repaired = archive.verify(VerifyOptions{RepairMode::Repair, false, ProgressDisplay::Never, 0});
  EXPECT_EQ(repaired.quarantined, 1u);
  EXPECT_FALSE(std::filesystem::exists(stray));
}

TEST(ServerArchive, RepairWaitsForAnImporterOnAnotherNode) {
  REQUIRE_SERVER();
  TemporaryFolder folder;
  testing::write_series(folder / "in", 2);
  const auto address = testing::archive_at(folder / "objects");
  Archive archive = Archive::open(address, OpenMode::CreateIfMissing);
  archive.import_paths({folder / "in"}, quiet());
  // Another node between writing an object and committing its row holds the store lock shared.
  Client importer(address);
  importer.run("SELECT pg_advisory_lock_shared(" + std::to_string(postgres::kStoreLockKey) + ")");
  std::atomic<bool> repaired = false;
  std::thread repair([&] {
    Archive own = Archive::open(address);
    own.verify(RepairMode::Repair, ProgressDisplay::Never);
    repaired = true;
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  EXPECT_FALSE(repaired) << "repair ran while another node was importing";
  importer.run("SELECT pg_advisory_unlock_shared(" + std::to_string(postgres::kStoreLockKey) + ")");
  repair.join();
  EXPECT_TRUE(repaired);
}

}  // namespace
}  // namespace maxillo
