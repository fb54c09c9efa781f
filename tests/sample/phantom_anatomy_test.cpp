// Each landmark sits on the structure it names; cavities, soft tissue and teeth are where and
// as large as designed.
#include "phantom_probe.h"
#include "sample/phantom_dentition.h"
#include "sample/phantom_design.h"

namespace maxillo::test {
namespace {

const Phantom& ph() { return default_phantom(); }
Eigen::Vector3d L(const char* label) { return landmark(ph(), label); }

bool is_bone(Tissue t) { return t == Tissue::kBone || t == Tissue::kMandible; }

TEST(PhantomAnatomy, SkeletalLandmarksOnBoneSurfaces) {
  // On the bone (within one voxel) with soft tissue just in front.
  for (const char* label : {"N", "A", "ANS"}) {
    EXPECT_TRUE(near(ph(), L(label), Tissue::kBone)) << label;
    EXPECT_EQ(tissue_at(ph(), L(label) + 2 * kAnterior), Tissue::kSoftTissue) << label;
  }
  for (const char* label : {"B", "Pog"}) {
    EXPECT_TRUE(near(ph(), L(label), Tissue::kMandible)) << label;
    EXPECT_EQ(tissue_at(ph(), L(label) + 2 * kAnterior), Tissue::kSoftTissue) << label;
  }
  for (const char* label : {"Me", "Gn", "GoR", "GoL", "ArR", "ArL"})
    EXPECT_TRUE(near(ph(), L(label), Tissue::kMandible)) << label;
  EXPECT_EQ(tissue_at(ph(), L("Me") + 2 * kInferior), Tissue::kSoftTissue);
  // Orbitale: bone below, orbit (soft tissue) above; porion: bone above, ear canal air below.
  for (const char* label : {"OrR", "OrL"}) {
    EXPECT_TRUE(near(ph(), L(label), Tissue::kBone)) << label;
    EXPECT_EQ(tissue_at(ph(), L(label) + 2 * kSuperior + 1 * kPosterior), Tissue::kSoftTissue) << label;
  }
  for (const char* label : {"PoR", "PoL"}) {
    EXPECT_TRUE(near(ph(), L(label), Tissue::kBone)) << label;
    Eigen::Vector3d inward(L(label).x() > 0 ? -2 : 2, 0, 0);
    EXPECT_EQ(tissue_at(ph(), L(label) + inward + 2 * kInferior), Tissue::kAir) << label;
  }
  // Sella: the pit (soft tissue) at S, its bony floor below.
  EXPECT_EQ(tissue_at(ph(), L("S")), Tissue::kSoftTissue);
  EXPECT_TRUE(near(ph(), L("S") + 7 * kInferior, Tissue::kBone));
}

// Articulare where a lateral cephalogram shows it: on the posterior border of the condylar process
// (the mandible in front, none behind) at the height where the cranial base's underside at the
// midline, at the same depth, begins (bone above, none below); 1.5 mm off, a voxel and a half.
TEST(PhantomAnatomy, ArticulareIsWhereTheCondylesBorderMeetsTheCranialBase) {
  for (const char* label : {"ArR", "ArL"}) {
    const Eigen::Vector3d ar = L(label);
    EXPECT_EQ(tissue_at(ph(), ar + 1.5 * kAnterior), Tissue::kMandible) << label;
    EXPECT_NE(tissue_at(ph(), ar + 1.5 * kPosterior), Tissue::kMandible) << label;
    const Eigen::Vector3d midline(0, ar.y(), ar.z());
    EXPECT_EQ(tissue_at(ph(), midline + 1.5 * kSuperior), Tissue::kBone) << label;
    EXPECT_FALSE(is_bone(tissue_at(ph(), midline + 1.5 * kInferior))) << label;
  }
}

TEST(PhantomAnatomy, NasalSpinesAreTheEndsOfThePalate) {
  // Bone just inside each end, none beyond it along the palatal plane.
  EXPECT_TRUE(is_bone(tissue_at(ph(), L("ANS") + 1 * kPosterior)));
  EXPECT_TRUE(is_bone(tissue_at(ph(), L("PNS") + 1 * kAnterior)));
  for (double t = 1.5; t <= 5; t += 0.5) {
    EXPECT_FALSE(is_bone(tissue_at(ph(), L("ANS") + t * kAnterior))) << t;
    EXPECT_FALSE(is_bone(tissue_at(ph(), L("PNS") + t * kPosterior))) << t;
  }
  // The palate is continuous between them (bone within one voxel of the ANS-PNS line).
  Eigen::Vector3d ans = L("ANS"), pns = L("PNS");
  for (double t = 0.02; t <= 0.98; t += 0.02)
    EXPECT_TRUE(near(ph(), pns + t * (ans - pns), Tissue::kBone)) << "palate gap at " << t;
}

TEST(PhantomAnatomy, PogonionIsMostAnteriorAndMentonLowestChinPoint) {
  const auto& g = ph().labels.geometry;
  int i0 = nearest_voxel(g, Eigen::Vector3d::Zero()).x();
  ASSERT_NEAR(g.world(Eigen::Vector3d(i0, 0, 0)).x(), 0, 1e-9);
  double most_anterior = -1e9, lowest = 1e9;
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j) {
      if (Tissue(ph().labels.labels[g.index(i0, j, k)]) != Tissue::kMandible) continue;
      Eigen::Vector3d p = g.world(Eigen::Vector3d(i0, j, k));
      if (p.z() < L("B").z()) most_anterior = std::max(most_anterior, -p.y());
      lowest = std::min(lowest, p.z());
    }
  EXPECT_NEAR(most_anterior, -L("Pog").y(), 1.0);
  EXPECT_LE(most_anterior, -L("Pog").y() + 1e-9);
  EXPECT_NEAR(lowest, L("Me").z(), 1.0);
  EXPECT_GE(lowest, L("Me").z() - 1e-9);
}

TEST(PhantomAnatomy, IncisorAndMolarLandmarksOnTheTeeth) {
  EXPECT_TRUE(near(ph(), L("U1"), Tissue::kUpperTooth));
  EXPECT_NE(tissue_at(ph(), L("U1") + 1.5 * kInferior + 1.5 * kAnterior), Tissue::kUpperTooth);
  EXPECT_TRUE(near(ph(), L("L1"), Tissue::kLowerTooth));
  EXPECT_NE(tissue_at(ph(), L("L1") + 1.5 * kSuperior), Tissue::kLowerTooth);
  for (const char* label : {"U6R", "U6L"}) EXPECT_TRUE(near(ph(), L(label), Tissue::kUpperTooth)) << label;
  for (const char* label : {"L6R", "L6L"}) EXPECT_TRUE(near(ph(), L(label), Tissue::kLowerTooth)) << label;
}

TEST(PhantomAnatomy, SoftTissueLandmarksOnTheSkin) {
  for (const char* label : {"NS", "Prn", "Sn", "Ls", "Li", "PogS"}) {
    EXPECT_TRUE(near(ph(), L(label), Tissue::kSoftTissue)) << label;
    EXPECT_EQ(tissue_at(ph(), L(label) + 2 * kAnterior), Tissue::kAir) << label;
    EXPECT_EQ(tissue_at(ph(), L(label) + 1.5 * kPosterior), Tissue::kSoftTissue) << label;
  }
}

TEST(PhantomAnatomy, SoftTissueThickness) {
  // Horizontal thickness from the bone landmark to the skin, and from Ls back to the incisors.
  double nasion = distance_to(ph(), L("N"), kAnterior, Tissue::kAir);
  double chin = distance_to(ph(), L("Pog"), kAnterior, Tissue::kAir);
  // Upper lip: from the skin at Ls's height, in front of the right central incisor, back to it.
  Eigen::Vector3d ls = L("Ls");
  ls.x() = L("U1").x();
  double upper_lip = distance_to(ph(), ls + 5 * kAnterior, kPosterior, Tissue::kUpperTooth) -
                     distance_to(ph(), ls + 5 * kAnterior, kPosterior, Tissue::kSoftTissue);
  EXPECT_GE(nasion, 5);
  EXPECT_LE(nasion, 7.5);
  EXPECT_GE(chin, 10);
  EXPECT_LE(chin, 12.5);
  EXPECT_GE(upper_lip, 12);
  EXPECT_LE(upper_lip, 15);
}

TEST(PhantomAnatomy, SinusesAreAirEnclosedByBone) {
  const auto& g = ph().labels.geometry;
  const auto& labels = ph().labels.labels;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
  int64_t count = 0;
  for (int k = 1; k + 1 < g.size.z(); ++k)
    for (int j = 1; j + 1 < g.size.y(); ++j)
      for (int i = 1; i + 1 < g.size.x(); ++i) {
        if (Tissue(labels[g.index(i, j, k)]) != Tissue::kSinusAir) continue;
        ++count;
        for (auto [di, dj, dk] : {std::tuple{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}) {
          Tissue n = Tissue(labels[g.index(i + di, j + dj, k + dk)]);
          ASSERT_TRUE(n == Tissue::kSinusAir || n == Tissue::kBone)
              << "sinus voxel (" << i << "," << j << "," << k << ") touches " << tissue_name(n);
        }
        Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k));
        if (p.x() > 0) {
          lo = lo.cwiseMin(p);
          hi = hi.cwiseMax(p);
        }
        // Real air in the CT (inside the cavity, away from the blurred wall).
        bool interior = true;
        for (int dk = -1; dk <= 1; ++dk)
          for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di)
              interior = interior && Tissue(labels[g.index(i + di, j + dj, k + dk)]) == Tissue::kSinusAir;
        if (interior) {
          EXPECT_LT(ph().ct.hu[g.index(i, j, k)], -900);
        }
      }
  ASSERT_GT(count, 0);
  Eigen::Vector3d size = hi - lo + g.spacing;  // left sinus, mm
  EXPECT_NEAR(size.x(), 25, 3);                // width
  EXPECT_NEAR(size.y(), 35, 3);                // antero-posterior
  EXPECT_NEAR(size.z(), 30, 3);                // height
  EXPECT_GT(lo.x(), 12);                       // lateral to the nasal cavity
}

TEST(PhantomAnatomy, SinusAirIsNotConnectedToOtherAirInTheCt) {
  // Flood fill (6-connected) through voxels below -400 HU from the centre of the left sinus:
  // what an air threshold would find must be exactly that sinus (no ostium, no leak).
  const Phantom& p = ph();
  const auto& g = p.ct.geometry;
  Eigen::Vector3i seed = nearest_voxel(g, Eigen::Vector3d(27.5, -40, -13));
  ASSERT_EQ(Tissue(p.labels.labels[g.index(seed.x(), seed.y(), seed.z())]), Tissue::kSinusAir);
  std::vector<uint8_t> seen(p.ct.hu.size(), 0);
  std::vector<Eigen::Vector3i> stack = {seed};
  seen[g.index(seed.x(), seed.y(), seed.z())] = 1;
  int64_t filled = 0;
  while (!stack.empty()) {
    Eigen::Vector3i v = stack.back();
    stack.pop_back();
    ++filled;
    ASSERT_EQ(Tissue(p.labels.labels[g.index(v.x(), v.y(), v.z())]), Tissue::kSinusAir)
        << "air path out of the sinus at voxel " << v.transpose();
    for (auto [di, dj, dk] : {std::tuple{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}) {
      Eigen::Vector3i n = v + Eigen::Vector3i(di, dj, dk);
      int64_t index = g.index(n.x(), n.y(), n.z());
      if (seen[index] || p.ct.hu[index] >= -400) continue;
      seen[index] = 1;
      stack.push_back(n);
    }
  }
  EXPECT_GT(filled, 5000);  // ~ (4/3) pi 12.5 17.5 14.5 mm^3 = 13 cm^3, minus the blurred rim
}

TEST(PhantomAnatomy, TeethOfTheTwoArchesTouchWithoutOverlapping) {
  // Analytic shapes: no point is inside an upper and a lower tooth.
  sample::PhantomDesign design = sample::make_design(PhantomSpec{});
  sample::Dentition teeth(design);
  int64_t both = 0;
  for (double x = -35; x <= 35; x += 0.25)
    for (double a = 25; a <= 78; a += 0.25)
      for (double z = -58; z <= -42; z += 0.25) {
        Eigen::Vector3d p(x, -a, z);
        if (teeth.inside_upper(p) && teeth.inside_lower(p)) ++both;
      }
  EXPECT_EQ(both, 0);
  // Voxels: lower tooth voxels with an upper tooth voxel within one voxel (3x3x3), all near
  // the occlusal plane, on both sides and at the incisors.
  const auto& g = ph().labels.geometry;
  const auto& labels = ph().labels.labels;
  int contacts = 0, left = 0, right = 0, incisors = 0;
  for (int k = 1; k + 1 < g.size.z(); ++k)
    for (int j = 1; j + 1 < g.size.y(); ++j)
      for (int i = 1; i + 1 < g.size.x(); ++i) {
        if (Tissue(labels[g.index(i, j, k)]) != Tissue::kLowerTooth) continue;
        Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k));
        if (!near(ph(), p, Tissue::kUpperTooth)) continue;
        ++contacts;
        EXPECT_NEAR(p.z(), design.occlusal_z(-p.y()), 3.5) << "contact away from the occlusal plane";
        (p.x() > 0 ? left : right) += std::abs(p.x()) > 20;
        incisors += std::abs(p.x()) < 6;
      }
  EXPECT_GT(contacts, 50);
  EXPECT_GT(left, 5);
  EXPECT_GT(right, 5);
  EXPECT_GT(incisors, 0);
}

TEST(PhantomAnatomy, HeadRestIsSeparateAndClearOfBone) {
  const auto& g = ph().labels.geometry;
  const auto& labels = ph().labels.labels;
  int64_t rest = 0, table = 0, rest_near_skin = 0;
  for (int k = 1; k + 1 < g.size.z(); ++k)
    for (int j = 1; j + 1 < g.size.y(); ++j)
      for (int i = 1; i + 1 < g.size.x(); ++i) {
        Tissue t = Tissue(labels[g.index(i, j, k)]);
        if (t == Tissue::kTable) ++table;
        if (t != Tissue::kHeadRest) continue;
        ++rest;
        for (Tissue n : tissues_near(ph(), g.world(Eigen::Vector3d(i, j, k)), 2)) {
          EXPECT_FALSE(is_bone(n)) << "head rest within 2 voxels of bone";
          if (n == Tissue::kSoftTissue) ++rest_near_skin;
        }
      }
  EXPECT_GT(rest, 10000);
  EXPECT_GT(table, 10000);
  EXPECT_GT(rest_near_skin, 0) << "the head rest should touch or nearly touch the occiput";
}

}  // namespace
}  // namespace maxillo::test
