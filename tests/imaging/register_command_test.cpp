// Black-box `maxillo register` on two DICOM folders: the synthetic head and a copy moved by a
// known rigid transform. The transform written to T.json must be rigid and close to the known
// one's inverse (same tolerance as rigid_registration_test.cpp: 0.2 mm, a tenth of a voxel).
#include <gtest/gtest.h>

#include "core/json.h"
#include "dicom/dicom_series_writer.h"
#include "imaging/synthetic_head.h"
#include "core/volume_resample.h"
#include "support/run_maxillo.h"
#include "support/temporary_folder.h"

namespace maxillo::testing {
namespace {

Eigen::Isometry3d read_matrix(const Json& rows) {
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = rows.at(size_t(r)).at(size_t(c)).get<double>();
  EXPECT_TRUE(m.row(3).isApprox(Eigen::RowVector4d(0, 0, 0, 1)));
  return Eigen::Isometry3d(m);
}

TEST(RegisterCommand, WritesARigidTransformCloseToTheKnownOne) {
  if (!std::filesystem::exists(MAXILLO_BINARY)) GTEST_SKIP() << MAXILLO_BINARY << " is not built";
  TemporaryFolder scratch("register-command");
  const Volume fixed = synthetic_head();
  const Eigen::Isometry3d known = oblique_move(4, {3, -4, 4});
  SeriesMetadata metadata;
  metadata.patient_id = "REG1";
  write_ct_series(fixed, metadata, scratch / "pre");
  write_ct_series(resample_rigid(fixed, known, fixed.geometry), metadata, scratch / "post");

  const auto run = run_maxillo({"register", (scratch / "pre").string(), (scratch / "post").string(), "--box",
                                "-70,-80,-40,70,80,90", "--out", (scratch / "T.json").string()},
                               scratch.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("registered in"), std::string::npos) << run.out;
  const Json t = Json::parse(slurp(scratch / "T.json"));
  const Eigen::Isometry3d moving_to_fixed = read_matrix(t.at("moving_to_fixed"));
  EXPECT_TRUE(moving_to_fixed.linear().isUnitary(1e-9));
  EXPECT_NEAR(moving_to_fixed.linear().determinant(), 1, 1e-9);
  EXPECT_LT(corner_rms(moving_to_fixed, known), 0.2);
  EXPECT_LT(t.at("metric").get<double>(), 0);
  EXPECT_GT(t.at("iterations").get<int>(), 0);
  EXPECT_EQ(t.at("box").at("min").at(2).get<double>(), -40);
  EXPECT_EQ(t.at("box").at("source").get<std::string>(), "--box");
  EXPECT_EQ(t.at("fixed").at("folder").get<std::string>(), (scratch / "pre").string());

  // A box outside the fixed CT is refused as bad input (exit 26), naming the box.
  const auto outside = run_maxillo(
      {"register", (scratch / "pre").string(), (scratch / "post").string(), "--box", "500,500,500,600,600,600"},
      scratch.path());
  EXPECT_EQ(outside.exit_code, 26) << outside.err;
  EXPECT_NE(outside.err.find("registration box"), std::string::npos) << outside.err;
}

}  // namespace
}  // namespace maxillo::testing
