#include "core/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include "core/error.h"

namespace maxillo {
namespace fs = std::filesystem;

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("maxillo-atomic-" + std::to_string(::getpid()));
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  fs::path folder_;
};

TEST_F(AtomicFileTest, RoundTripAndNoTemporaryLeftBehind) {
  write_file_atomically(folder_ / "a.txt", std::string_view("hello"));
  auto bytes = read_file(folder_ / "a.txt");
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size()), "hello");
  EXPECT_EQ(std::distance(fs::directory_iterator(folder_), fs::directory_iterator()), 1);
}

TEST_F(AtomicFileTest, OverwriteReplacesWholeContent) {
  write_file_atomically(folder_ / "a.txt", std::string_view("a much longer first version"));
  write_file_atomically(folder_ / "a.txt", std::string_view("short"));
  EXPECT_EQ(fs::file_size(folder_ / "a.txt"), 5u);
}

TEST_F(AtomicFileTest, MissingFileNamesPath) {
  try {
    read_file(folder_ / "absent.dcm");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kFileNotFound);
    EXPECT_NE(std::string(e.what()).find("absent.dcm"), std::string::npos);
  }
}

TEST_F(AtomicFileTest, WriteIntoMissingFolderFails) {
  EXPECT_THROW(write_file_atomically(folder_ / "no" / "such" / "a.txt", std::string_view("x")), Error);
}

}  // namespace maxillo
