// Registration errors that need no real data.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "dental/arch_registration.h"
#include "registration_error.h"

namespace maxillo::dental {
namespace {

using testing::registration_error;

TEST(ArchRegistration, AnEmptyScanIsAnError) {
  TriangleMesh empty, triangle;
  triangle.vertices.resize(3, 3);
  triangle.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  triangle.faces.resize(1, 3);
  triangle.faces << 0, 1, 2;
  EXPECT_EQ(registration_error(empty, triangle), "dental scan: an empty surface: nothing to register");
}

}  // namespace
}  // namespace maxillo::dental
