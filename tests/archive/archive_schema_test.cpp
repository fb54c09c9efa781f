// Schema migrations: an empty folder is upgraded to the newest version, re-opening changes
// nothing, and a schema newer than the program is refused.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <algorithm>

#include "archive/archive.h"
#include "core/resources.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {

int user_version(const std::filesystem::path& file) {
  sqlite3* db = nullptr;
  sqlite3_open(file.c_str(), &db);
  sqlite3_stmt* statement = nullptr;
  sqlite3_prepare_v2(db, "PRAGMA user_version", -1, &statement, nullptr);
  sqlite3_step(statement);
  int version = sqlite3_column_int(statement, 0);
  sqlite3_finalize(statement);
  sqlite3_close(db);
  return version;
}

void set_user_version(const std::filesystem::path& file, int version) {
  sqlite3* db = nullptr;
  sqlite3_open(file.c_str(), &db);
  sqlite3_exec(db, ("PRAGMA user_version = " + std::to_string(version)).c_str(), nullptr, nullptr, nullptr);
  sqlite3_close(db);
}

TEST(ArchiveSchema, MigrationsAreEmbeddedAndNumberedFromOne) {
  std::vector<std::string> migrations;  // db/NNN_*.sql; dialect variants sit in db/postgresql/
  for (const auto& path : list_resources("db/"))
    if (path.find('/', 3) == std::string::npos) migrations.push_back(path);
  ASSERT_FALSE(migrations.empty());
  EXPECT_EQ(migrations.front(), "db/001_initial.sql");
  EXPECT_EQ(Archive::newest_schema_version(), int(migrations.size()));
  // A dialect variant replaces a numbered migration, never adds one.
  for (const auto& variant : list_resources("db/postgresql/"))
    EXPECT_NE(std::find(migrations.begin(), migrations.end(), "db/" + variant.substr(14)), migrations.end()) << variant;
}

TEST(ArchiveSchema, EmptyFolderIsUpgradedToTheNewestVersionAndReopeningIsIdempotent) {
  testing::TemporaryFolder folder;
  auto archive_folder = folder / "archive";
  {
    Archive archive = Archive::open(archive_folder, OpenMode::CreateIfMissing);
    EXPECT_EQ(archive.schema_version(), Archive::newest_schema_version());
    EXPECT_TRUE(archive.patients().empty());
    EXPECT_TRUE(archive.cases().empty());
  }
  EXPECT_EQ(user_version(archive_folder / "index.sqlite"), Archive::newest_schema_version());
  for (int n = 0; n < 2; ++n) {
    Archive archive = Archive::open(archive_folder, OpenMode::CreateIfMissing);
    EXPECT_EQ(archive.schema_version(), Archive::newest_schema_version());
  }
}

TEST(ArchiveSchema, NewerSchemaIsRefused) {
  testing::TemporaryFolder folder;
  { Archive::open(folder.path(), OpenMode::CreateIfMissing); }
  set_user_version(folder / "index.sqlite", Archive::newest_schema_version() + 1);
  try {
    Archive::open(folder.path(), OpenMode::CreateIfMissing);
    FAIL() << "a newer schema must be refused";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kSchemaTooNew);
  }
}

}  // namespace
}  // namespace maxillo
