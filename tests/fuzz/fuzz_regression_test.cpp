// Every seed of tests/fuzz/corpus/<target>/ and every finding saved in tests/fuzz/regressions/
// <target>/ goes through its fuzz entry in the normal build: each must end normally or with a
// maxillo::Error, never another exception (a crash or hang ends the test run, which fails too).
#include <gtest/gtest.h>

#include <string>

#include "core/atomic_file.h"
#include "core/error.h"
#include "fuzz_entries.h"

namespace maxillo::fuzzing {
namespace {

const std::filesystem::path kTests = std::filesystem::path(MAXILLO_SOURCE_DIR) / "tests";

std::vector<std::filesystem::path> inputs_of(const Target& target) {
  std::vector<std::filesystem::path> folders = {kTests / "fuzz" / "corpus" / target.corpus,
                                                kTests / "fuzz" / "regressions" / target.name};
  if (target.extra) folders.push_back(kTests / target.extra);
  std::vector<std::filesystem::path> files;
  for (const auto& folder : folders) {
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error))
      if (entry.is_regular_file() && entry.path().extension() != ".md") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

class FuzzInputs : public ::testing::TestWithParam<Target> {};

TEST_P(FuzzInputs, EverySeedAndFindingEndsNormallyOrWithAnError) {
  const Target target = GetParam();
  const auto files = inputs_of(target);
  ASSERT_FALSE(files.empty()) << "no seeds for " << target.name;
  for (const auto& file : files) {
    const auto bytes = read_file(file);
    try {
      target.entry(bytes);
    } catch (const std::exception& e) {
      ADD_FAILURE() << file << ": " << e.what();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzInputs, ::testing::ValuesIn(kTargets),
                         [](const ::testing::TestParamInfo<Target>& param) { return std::string(param.param.name); });

}  // namespace
}  // namespace maxillo::fuzzing
