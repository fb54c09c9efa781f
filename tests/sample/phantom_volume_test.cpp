// The volume itself: grid, HU of materials, mirror symmetry, noise, determinism.
#include "phantom_probe.h"

namespace maxillo::test {
namespace {

TEST(PhantomVolume, GridCoversTheHeadAndIsCentredOnTheMidSagittalPlane) {
  const Phantom& ph = default_phantom();
  const auto& g = ph.ct.geometry;
  EXPECT_EQ(g.spacing, Eigen::Vector3d::Constant(1.0));
  EXPECT_EQ(g.direction, Eigen::Matrix3d::Identity());
  EXPECT_EQ(ph.ct.hu.size(), size_t(g.voxel_count()));
  EXPECT_EQ(ph.labels.labels.size(), size_t(g.voxel_count()));
  EXPECT_EQ(g.size.x() % 2, 1);
  EXPECT_DOUBLE_EQ(g.origin.x() + g.spacing.x() * (g.size.x() - 1), -g.origin.x());
  // A margin of air around the head: no body voxel on the lateral faces (the head rest and
  // table are wider than the field of view, as in real scans).
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i : {0, g.size.x() - 1}) {
        Tissue t = Tissue(ph.labels.labels[g.index(i, j, k)]);
        EXPECT_TRUE(t == Tissue::kAir || t == Tissue::kTable || t == Tissue::kHeadRest)
            << "body touches the lateral face";
      }
}

TEST(PhantomVolume, MaterialsHaveTheirHounsfieldUnits) {
  const Phantom& ph = clean_phantom();
  auto hu = [&](const Eigen::Vector3d& p) {
    const auto& g = ph.ct.geometry;
    Eigen::Vector3i v = nearest_voxel(g, p);
    return ph.ct.hu[g.index(v.x(), v.y(), v.z())];
  };
  EXPECT_EQ(hu({0, 20, 60}), 35);                                      // brain
  EXPECT_EQ(hu({0, 20, 40 + 85 - 1}), 1500);                           // outer table of the vault (cortical)
  EXPECT_EQ(hu({0, 20, 40 + 85 - 3.5}), 450);                          // diploe (cancellous)
  EXPECT_EQ(hu({27.5, -40, -13}), -1000);                              // sinus
  EXPECT_EQ(hu(landmark(ph, "U1") + Eigen::Vector3d(0, 0, 2)), 2800);  // incisor enamel
  EXPECT_EQ(hu({0, -110, 0}), -1000);                                  // air in front of the face
  EXPECT_EQ(hu({0, 60, -100}), 40);                                    // neck soft tissue
  // Enamel, cortical bone, soft tissue and air are present in expected amounts.
  int64_t enamel = 0, bone = 0;
  for (int16_t v : ph.ct.hu) {
    enamel += v == 2800;
    bone += v == 1500;
  }
  EXPECT_GT(enamel, 5000);
  EXPECT_GT(bone, 100000);
}

TEST(PhantomVolume, MirrorSymmetricAboutMidSagittalPlane) {
  const Phantom& ph = clean_phantom();
  const auto& g = ph.ct.geometry;
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x() / 2; ++i) {
        int m = g.size.x() - 1 - i;
        ASSERT_EQ(ph.ct.hu[g.index(i, j, k)], ph.ct.hu[g.index(m, j, k)]) << i << "," << j << "," << k;
        ASSERT_EQ(ph.labels.labels[g.index(i, j, k)], ph.labels.labels[g.index(m, j, k)]);
      }
}

TEST(PhantomVolume, NoiseHasTheRequestedSigmaAndSameLabels) {
  const Phantom& noisy = default_phantom();
  const Phantom& clean = clean_phantom();
  ASSERT_EQ(noisy.labels.labels, clean.labels.labels);
  // In the air in front of the face neither blur nor noise clamp (-1000 + noise > -1024 mostly):
  // estimate sigma from far-field air voxels above -1024.
  const auto& g = noisy.ct.geometry;
  double sum = 0, sum2 = 0;
  int64_t n = 0;
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        double v = noisy.ct.hu[g.index(i, j, k)] + 1000.0;
        sum += v;
        sum2 += v * v;
        ++n;
      }
  double mean = sum / n, sigma = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 0, 1);
  EXPECT_NEAR(sigma, 15, 1);
}

TEST(PhantomVolume, Deterministic) {
  PhantomSpec spec;
  spec.spacing_mm = 2.5;
  Phantom a = make_phantom(spec), b = make_phantom(spec);
  EXPECT_EQ(a.ct.hu, b.ct.hu);
  EXPECT_EQ(a.labels.labels, b.labels.labels);
  spec.noise_seed += 1;
  Phantom c = make_phantom(spec);
  EXPECT_NE(a.ct.hu, c.ct.hu);
  EXPECT_EQ(a.labels.labels, c.labels.labels);
}

}  // namespace
}  // namespace maxillo::test
