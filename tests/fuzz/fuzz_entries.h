#pragma once
// What each fuzz target feeds its input to. Shared by the libFuzzer targets (fuzz_*.cpp, built
// with clang when MAXILLO_FUZZ is on) and by fuzz_regression_test.cpp, which replays every seed
// and every saved finding through the same functions in the normal build, so CI checks them all.
//
// A target may throw maxillo::Error (bad input, said clearly): that is the expected outcome for
// most inputs. Anything else that escapes (another exception type, a crash, a hang, a leak, a
// sanitizer report) is a finding.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

namespace maxillo::fuzzing {

using Entry = std::function<void(std::span<const std::byte>)>;

void dicom_header(std::span<const std::byte> bytes);  // import parsing
void dicom_slice(std::span<const std::byte> bytes);   // pixel decoding to HU
void landmarks(std::span<const std::byte> bytes);     // the first byte picks CSV, .fcsv or .mrk.json
void plan_json(std::span<const std::byte> bytes);     // a plan file
void mesh_file(std::span<const std::byte> bytes);     // the first byte picks STL or PLY
void cohort_csv(std::span<const std::byte> bytes);    // a follow-up cohort

struct Target {
  const char* name;    // findings are saved in tests/fuzz/regressions/<name>/
  const char* corpus;  // seeds: tests/fuzz/corpus/<corpus>/
  const char* extra;   // more seeds elsewhere under tests/, or nullptr
  void (*entry)(std::span<const std::byte>);
};
inline constexpr Target kTargets[] = {{"dicom_header", "dicom", "data/bad-inputs", dicom_header},
                                      {"dicom_slice", "dicom", "data/bad-inputs", dicom_slice},
                                      {"landmarks", "landmarks", nullptr, landmarks},
                                      {"plan_json", "plan_json", nullptr, plan_json},
                                      {"mesh_file", "mesh_file", nullptr, mesh_file},
                                      {"cohort_csv", "cohort_csv", nullptr, cohort_csv}};

}  // namespace maxillo::fuzzing
