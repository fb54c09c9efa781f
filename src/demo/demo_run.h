#pragma once
// `maxillo demo`: every stage of the three jobs on the synthetic phantom, from nothing to the
// reports. The phantom's CT is pushed over DICOM to a storage server of ours (as a scanner
// would), its occlusion found, a distraction plan applied, the face predicted, a synthetic
// post-operative CT made and validated, the nightly summary run, the consultation report
// written and sent back over DICOM to a second server standing in for the PACS, and the
// sample cohort's follow-up report written.
#include <filesystem>

#include "core/json.h"
#include "sample/phantom.h"

namespace maxillo::demo {

struct DemoOptions {
  std::filesystem::path out = "demo-output";  // created: sample/, archive/, report.pdf, nightly/, ...
  SkeletalClass skeletal_class = SkeletalClass::I;
  std::filesystem::path archive_dir;  // the archive (a folder or a PostgreSQL URI); empty: out/archive
};

// Runs the demo and returns its summary: the files written, what went over DICOM, the plan's
// and the validation's figures and the stage times ("timing").
Json run_demo(const DemoOptions& options);

}  // namespace maxillo::demo
