// segment_tissues on a synthetic head: an ellipsoid of soft tissue with a skull shell, a dense
// "tooth", an enclosed air cell, a stray bone speck, and a curved head rest touching the back.
#include "imaging/segmentation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace maxillo {
namespace {

struct SyntheticHead {
  Volume volume;
  std::vector<uint8_t> in_head, in_headrest_far;  // ground truth per voxel
};

// 2 mm voxels; head centred at c with semi-axes (60, 80, 70) mm (x, y posterior, z).
SyntheticHead make_head() {
  SyntheticHead h;
  VolumeGeometry& g = h.volume.geometry;
  g.size = {80, 110, 90};
  g.spacing = {2, 2, 2};
  h.volume.hu.assign(size_t(g.voxel_count()), -1000);
  h.in_head.assign(h.volume.hu.size(), 0);
  h.in_headrest_far.assign(h.volume.hu.size(), 0);
  const Eigen::Vector3d c(80, 100, 90), axes(60, 80, 70);
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k));
        const size_t n = size_t(g.index(i, j, k));
        const double e = (p - c).cwiseQuotient(axes).norm();  // 1 on the skin
        int16_t& hu = h.volume.hu[n];
        if (e <= 1) {
          h.in_head[n] = 1;
          hu = 40;
          if (e > 0.85 && e < 0.93) hu = 900;                                  // skull
          if ((p - (c + Eigen::Vector3d(0, -55, -30))).norm() < 6) hu = 2200;  // tooth
          if ((p - (c + Eigen::Vector3d(20, -20, 10))).norm() < 8) hu = -950;  // air cell
          if ((p - (c + Eigen::Vector3d(-20, 0, 0))).norm() < 1.5) hu = 700;   // bone speck
        }
        // Head rest: a cylindrical shell 4 mm thick around an axis along z, under the back of
        // the head (posterior = +y), touching the skin along the mid-sagittal line.
        const double r = std::hypot(p.x() - c.x(), p.y() - (c.y() - 30));
        if (p.y() > c.y() + 40 && r >= 110 && r <= 114 && e > 1) {
          hu = 100;
          if (p.y() > c.y() + 40 && std::abs(p.x() - c.x()) > 30) h.in_headrest_far[n] = 1;
        }
      }
  return h;
}

TEST(Segmentation, SyntheticHeadLabelsAndHeadRestRemoval) {
  const SyntheticHead h = make_head();
  // Without the opening the head rest stays attached to the body ...
  LabelVolume attached = segment_tissues(h.volume, {.headrest_gap_mm = 0});
  int64_t headrest_kept = 0;
  for (size_t n = 0; n < h.in_headrest_far.size(); ++n) headrest_kept += h.in_headrest_far[n] && attached.labels[n];
  ASSERT_GT(headrest_kept, 100) << "the synthetic head rest does not touch the head";

  // ... with it, the head rest is gone and the head is whole.
  LabelVolume labels = segment_tissues(h.volume);
  int64_t head = 0, head_labelled = 0, headrest_left = 0, outside_labelled = 0, outside_far = 0;
  const Eigen::Vector3d centre(80, 100, 90), semi_axes(60, 80, 70);
  int64_t counts[5] = {};
  for (size_t n = 0; n < labels.labels.size(); ++n) {
    ++counts[labels.labels[n]];
    head += h.in_head[n];
    head_labelled += h.in_head[n] && labels.labels[n];
    headrest_left += h.in_headrest_far[n] && labels.labels[n];
    if (!h.in_head[n] && labels.labels[n]) {
      ++outside_labelled;
      // Where the head rest touches, material within the opening radius (3 mm, rounded up to
      // 2 voxels = 4 mm) of the head stays: nothing labelled may lie further out than ~5 mm.
      const int i = int(n % 80), j = int(n / 80 % 110), k = int(n / (80 * 110));
      const double e = (labels.geometry.world(Eigen::Vector3d(i, j, k)) - centre).cwiseQuotient(semi_axes).norm();
      if ((e - 1) * semi_axes.minCoeff() > 5) ++outside_far;
    }
  }
  EXPECT_EQ(headrest_left, 0);
  EXPECT_GT(double(head_labelled), 0.999 * double(head));
  EXPECT_EQ(outside_far, 0) << "only the contact strip may stay";
  EXPECT_LT(double(outside_labelled), 0.005 * double(head));

  const VolumeGeometry& g = labels.geometry;
  auto label_at = [&](const Eigen::Vector3d& lps) {
    Eigen::Vector3d ijk = g.continuous_index(lps);
    return labels
        .labels[size_t(g.index(int(std::lround(ijk.x())), int(std::lround(ijk.y())), int(std::lround(ijk.z()))))];
  };
  const Eigen::Vector3d c(80, 100, 90);
  EXPECT_EQ(label_at(c), kSoftTissue);
  EXPECT_EQ(label_at(c + Eigen::Vector3d(0, -55, -30)), kTeeth);
  EXPECT_EQ(label_at(c + Eigen::Vector3d(20, -20, 10)), kEnclosedAir);
  EXPECT_EQ(label_at(c + Eigen::Vector3d(-20, 0, 0)), kSoftTissue) << "a bone speck below 200 mm3 is dropped";
  EXPECT_EQ(label_at(c + Eigen::Vector3d(0, 0, 0.89 * 70)), kBone);
  EXPECT_GT(counts[kBone], 1000);
  EXPECT_GT(counts[kEnclosedAir], 100);
}

// A nose whose walls are thinner than the opening's ball (as the cadaver head's alae, septum and
// tip, 4-5 mm with the nostrils behind them): the opening cuts it off whole and the dilation back
// reaches only its root. It is a small piece cut off the body, so it is body again; the head rest
// (a far larger piece) stays outside.
TEST(Segmentation, AThinNoseAndEarAreKeptWhileAPadAndTheHeadRestGo) {
  SyntheticHead h = make_head();
  const VolumeGeometry& g = h.volume.geometry;
  const Eigen::Vector3d tip_centre(80, 20, 90);  // on the face's front (y = c.y - 80)
  const Eigen::Vector3d outer(12, 25, 20), inner(8, 21, 16);
  std::vector<uint8_t> in_nose(h.volume.hu.size(), 0);
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k));
        const size_t n = size_t(g.index(i, j, k));
        if (h.in_head[n] || p.y() > tip_centre.y()) continue;
        const Eigen::Vector3d d = p - tip_centre;
        if (d.cwiseQuotient(outer).norm() <= 1 && d.cwiseQuotient(inner).norm() > 1) {
          h.volume.hu[n] = 40;
          in_nose[n] = 1;
        }
      }
  // Two plates 8 mm (4 voxels) thick on the head's sides (x = 20 and x = 140), 20 x 20 mm,
  // thinner than the 2 mm grid's ball (5 voxels across): on the right an "ear" of soft tissue's
  // grey, on the left a pad of foam (-300 HU). The dilation back reaches into both.
  std::vector<uint8_t> in_ear(h.volume.hu.size(), 0), in_pad(h.volume.hu.size(), 0);
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k));
        const size_t n = size_t(g.index(i, j, k));
        if (h.in_head[n] || std::abs(p.y() - 100) > 10 || std::abs(p.z() - 90) > 10) continue;
        if (p.x() > 11 && p.x() < 20) {
          h.volume.hu[n] = 30;
          in_ear[n] = 1;
        } else if (p.x() > 140 && p.x() < 149) {
          h.volume.hu[n] = -300;
          in_pad[n] = 1;
        }
      }
  auto kept_of = [&](const std::vector<uint8_t>& truth, const LabelVolume& labels) {
    int64_t kept = 0, total = 0;
    for (size_t n = 0; n < truth.size(); ++n) {
      total += truth[n];
      kept += truth[n] && labels.labels[n] != kBackground;
    }
    return double(kept) / double(total);
  };
  auto nose_kept = [&](const LabelVolume& labels) {
    int64_t kept = 0, total = 0;
    for (size_t n = 0; n < in_nose.size(); ++n) {
      total += in_nose[n];
      kept += in_nose[n] && labels.labels[n] == kSoftTissue;
    }
    return double(kept) / double(total);
  };
  auto headrest_left = [&](const LabelVolume& labels) {
    int64_t left = 0;
    for (size_t n = 0; n < h.in_headrest_far.size(); ++n) left += h.in_headrest_far[n] && labels.labels[n];
    return left;
  };
  const LabelVolume without = segment_tissues(h.volume, {.max_restored_piece_mm3 = 0});
  EXPECT_LT(nose_kept(without), 0.5) << "the walls are not thin enough for the opening to cut the nose";
  EXPECT_EQ(headrest_left(without), 0);

  EXPECT_LT(kept_of(in_ear, without), 0.9);
  EXPECT_LT(kept_of(in_pad, without), 0.9);

  const LabelVolume labels = segment_tissues(h.volume);
  EXPECT_GT(nose_kept(labels), 0.999);
  EXPECT_GT(kept_of(in_ear, labels), 0.999);
  EXPECT_EQ(kept_of(in_pad, labels), kept_of(in_pad, without)) << "a pad's grey is not soft tissue's";
  EXPECT_EQ(headrest_left(labels), 0) << "the head rest is a larger piece and stays outside";
}

TEST(Segmentation, RestrictToMaskMakesTheMaskBoundaryTheIsoLevel) {
  Volume v;
  v.geometry.size = {4, 1, 1};
  v.hu = {-1000, 500, -1000, 500};
  LabelVolume mask{v.geometry, {1, 1, 0, 0}};  // a hole voxel inside, a removed island outside
  Volume r = restrict_to_mask(v, mask, -400);
  EXPECT_EQ(r.hu, (std::vector<int16_t>{-399, 500, -1000, -401}));
  EXPECT_EQ(select_labels(LabelVolume{v.geometry, {0, 3, 4, 2}}, kBone, kTeeth).labels,
            (std::vector<uint8_t>{0, 1, 1, 0}));
}

}  // namespace
}  // namespace maxillo
