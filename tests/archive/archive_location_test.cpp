// --archive names a folder or a PostgreSQL server with its shared object folder.
#include <gtest/gtest.h>

#include "archive/archive_location.h"
#include "core/error.h"

namespace maxillo {
namespace {

ErrorCode parse_error(const std::string& text, std::string* reason = nullptr) {
  try {
    parse_archive_location(text);
  } catch (const Error& e) {
    if (reason) *reason = e.reason();
    return e.code();
  }
  return ErrorCode::kProcessing;
}

TEST(ArchiveLocation, AFolderIsTakenAsItIs) {
  auto location = parse_archive_location("relative/archive");
  EXPECT_TRUE(location.embedded());
  EXPECT_EQ(location.folder, "relative/archive");
  EXPECT_EQ(location.objects_folder(), "relative/archive/objects");
}

TEST(ArchiveLocation, TheObjectsParameterIsTakenOutOfTheUriHandedToLibpq) {
  auto location =
      parse_archive_location("postgresql://maxillo@db.example:5433/archive?sslmode=require&objects=/shared/objects");
  EXPECT_FALSE(location.embedded());
  EXPECT_EQ(location.folder, "/shared/objects");
  EXPECT_EQ(location.objects_folder(), "/shared/objects");
  EXPECT_EQ(location.server_uri, "postgresql://maxillo@db.example:5433/archive?sslmode=require&connect_timeout=10");
}

TEST(ArchiveLocation, AGivenConnectTimeoutIsKeptAndTheShortSchemeWorks) {
  auto location = parse_archive_location("postgres://h/db?connect_timeout=3&objects=/o");
  EXPECT_EQ(location.server_uri, "postgres://h/db?connect_timeout=3");
}

TEST(ArchiveLocation, ThePasswordIsNeverShown) {
  auto location = parse_archive_location("postgresql://maxillo:s3cret@host/db?objects=/o");
  EXPECT_EQ(location.shown.find("s3cret"), std::string::npos) << location.shown;
  EXPECT_NE(location.server_uri.find("s3cret"), std::string::npos);  // libpq needs it
  std::string reason;
  parse_error("postgresql://maxillo:s3cret@host/db", &reason);
  EXPECT_EQ(reason.find("s3cret"), std::string::npos) << reason;
}

TEST(ArchiveLocation, PercentEncodedFoldersAreDecoded) {
  EXPECT_EQ(parse_archive_location("postgresql://h/db?objects=/mnt/shared%20store/a%26b").folder,
            "/mnt/shared store/a&b");
}

TEST(ArchiveLocation, MalformedAddressesAreRefusedInTheArchiveRangeWithTheReason) {
  std::string reason;
  EXPECT_EQ(parse_error("postgresql://host/db", &reason), ErrorCode::kBadArchiveAddress);
  EXPECT_NE(reason.find("objects"), std::string::npos) << reason;
  EXPECT_EQ(parse_error("postgresql://host/db?objects=relative/folder", &reason), ErrorCode::kBadArchiveAddress);
  EXPECT_NE(reason.find("absolute"), std::string::npos) << reason;
  EXPECT_EQ(parse_error("postgresql://host?objects=/o", &reason), ErrorCode::kBadArchiveAddress);
  EXPECT_NE(reason.find("database"), std::string::npos) << reason;
  EXPECT_EQ(parse_error("postgresql://host/db?objects=/a%2"), ErrorCode::kBadArchiveAddress);
  EXPECT_GE(exit_code_for(ErrorCode::kBadArchiveAddress), 40);
  EXPECT_LT(exit_code_for(ErrorCode::kBadArchiveAddress), 60);
}

}  // namespace
}  // namespace maxillo
