#pragma once
// A case in a fresh archive of a test's own (a small CT series of patient P9 imported), for
// storing and reading back a case's records.
#include <cstdint>

#include "archive/archive.h"
#include "archive/archive_fixture.h"
#include "support/temporary_folder.h"

namespace maxillo::testing {

struct ArchivedCase {
  TemporaryFolder folder;
  Archive archive = Archive::open(folder.path() / "archive", OpenMode::CreateIfMissing);
  int64_t case_id = 0;
  ArchivedCase() {
    write_series(folder.path() / "dicom", 3, "P9");
    archive.import_paths({folder.path() / "dicom"});
    case_id = archive.resolve_case("P9");
  }
};

}  // namespace maxillo::testing
