#pragma once
// The real cadaver head (../shared/data/cthead-stanford) wrapped as a DICOM CT series by
// scripts/cthead-to-dicom, as a clinic would bring it in, for the black-box tests that import it.
#include <filesystem>

#include "support/run_command.h"

namespace maxillo::testing {

inline std::filesystem::path cadaver_data() { return std::filesystem::path(MAXILLO_SHARED_DATA) / "cthead-stanford"; }

inline bool cadaver_present() { return std::filesystem::exists(cadaver_data() / "slices" / "CThead.1"); }

// Writes the series into `out`; the script's exit status and output.
inline CommandResult wrap_cadaver_as_dicom(const std::filesystem::path& out) {
  return run_command(std::string("bash ") + MAXILLO_SOURCE_DIR + "/scripts/cthead-to-dicom " + quote(out) + " --data " +
                     quote(cadaver_data() / "slices") + " --maxillo " + MAXILLO_BINARY + " 2>&1");
}

}  // namespace maxillo::testing
