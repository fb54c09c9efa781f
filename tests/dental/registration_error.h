#pragma once
// The error register_arch throws for a scan and teeth, or "" when it registers.
#include <string>

#include "core/error.h"
#include "dental/arch_registration.h"

namespace maxillo::dental::testing {

inline std::string registration_error(const TriangleMesh& scan, const TriangleMesh& teeth) {
  try {
    register_arch(scan, teeth);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace maxillo::dental::testing
