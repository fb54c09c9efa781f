#pragma once
// Benchmark support: an archive index filled with synthetic rows in bulk, to time queries on
// an index of a hospital's size (`maxillo bench index`). Each patient has one study with a
// pre-operative and a post-operative CT series of equal size and its default case; instances
// name objects that do not exist and the rows are not journalled, so such an archive is for
// timing only (verify reports it as data loss).
#include <cstdint>
#include <filesystem>

namespace maxillo {

struct SyntheticIndexSize {
  int64_t patients = 1000;
  int64_t instances = 500000;  // spread evenly over the 2 series of every patient
};

// Fills the (new, empty) archive at `address` in one transaction per 100 patients.
void fill_synthetic_index(const std::filesystem::path& address, const SyntheticIndexSize& size);

}  // namespace maxillo
