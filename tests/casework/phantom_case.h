#pragma once
// The phantom as an archived case: written as DICOM at the given spacing, imported into a new
// archive in `folder`, its analytic landmarks attached.
#include <gtest/gtest.h>

#include "archive_fixture.h"
#include "records/case_landmarks.h"
#include "records/plan_archive.h"
#include "casework/plan/planned_case.h"
#include "casework/sample/sample_case.h"

namespace maxillo::casework::testing_support {

struct PhantomCase {
  Archive archive;
  int64_t case_id = 0;
};

inline PhantomCase archived_phantom(const std::filesystem::path& folder, double spacing_mm) {
  const SampleCase sample = write_sample_case(SkeletalClass::I, spacing_mm, folder / "sample");
  Archive archive = Archive::open(folder / "archive", OpenMode::CreateIfMissing);
  if (!archive.import_paths({sample.ct_folder}, testing::quiet()).all_ok())
    throw std::runtime_error("the phantom did not import");
  const int64_t case_id = archive.resolve_case(kPhantomPatientId);
  records::attach_landmarks(archive, case_id, sample.landmarks, "phantom");
  return {std::move(archive), case_id};
}

// The archived phantom with a distraction plan (advancement only) stored, loaded as a planned case.
inline PlannedCase planned_phantom(const std::filesystem::path& folder, double spacing_mm, double advancement_mm) {
  auto [archive, case_id] = archived_phantom(folder, spacing_mm);
  records::store_plan(archive, case_id,
                      planning::distraction_plan({.advancement_mm = advancement_mm, .widening_mm = 0}, "test"));
  return load_planned_case(archive, case_id);
}

}  // namespace maxillo::casework::testing_support
