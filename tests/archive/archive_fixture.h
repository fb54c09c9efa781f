#pragma once
// Shared helpers of the archive tests: small CT series written by the real series writer
// (dicom/dicom_fixture.h) and archives to import them into.
#include "archive/archive.h"
#include "dicom/dicom_fixture.h"
#include "support/temporary_folder.h"
#include "support/test_archive.h"

namespace maxillo::testing {

// Import options for tests: no progress bar.
inline ImportOptions quiet() {
  ImportOptions options;
  options.progress = ProgressDisplay::Never;
  return options;
}

}  // namespace maxillo::testing
