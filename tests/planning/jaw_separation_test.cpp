// Telling the jaws apart on a CT segmentation: on the phantom's CT the result must agree with
// the phantom's own labels (its construction is the known answer).
#include <gtest/gtest.h>

#include <map>

#include "core/error.h"
#include "imaging/segmentation.h"
#include "planning/jaw_separation.h"
#include "sample/phantom.h"

namespace maxillo::planning {
namespace {

// How the separated labels agree with the phantom's own, per true label.
void expect_agreement(const Phantom& phantom, const LabelVolume& separated) {
  // Per true label: how many voxels got each label.
  std::map<int, std::map<int, int64_t>> confusion;
  for (size_t v = 0; v < separated.labels.size(); ++v) ++confusion[phantom.labels.labels[v]][separated.labels[v]];
  auto share = [&](Tissue truth, Tissue got) {
    int64_t total = 0;
    for (auto [label, n] : confusion[int(truth)]) total += n;
    return total ? double(confusion[int(truth)][int(got)]) / double(total) : 0.0;
  };
  // The tops of the rami (condyles, coronoid processes) stay with the skull, where they touch it
  // on a CT; the rest of the mandible is found, its cortex sometimes labelled as teeth.
  EXPECT_GT(share(Tissue::kMandible, Tissue::kMandible) + share(Tissue::kMandible, Tissue::kLowerTooth), 0.9);
  EXPECT_LT(share(Tissue::kBone, Tissue::kMandible), 0.01);
  EXPECT_GT(share(Tissue::kUpperTooth, Tissue::kUpperTooth) + share(Tissue::kUpperTooth, Tissue::kBone), 0.95);
  EXPECT_LT(share(Tissue::kUpperTooth, Tissue::kMandible) + share(Tissue::kUpperTooth, Tissue::kLowerTooth), 0.05);
  EXPECT_LT(share(Tissue::kLowerTooth, Tissue::kUpperTooth) + share(Tissue::kLowerTooth, Tissue::kBone), 0.05);
}

Phantom phantom_at_1mm() {
  PhantomSpec spec;
  spec.spacing_mm = 1.0;
  return make_phantom(spec);
}

TEST(JawSeparation, AgreesWithThePhantomsOwnLabels) {
  const auto phantom = phantom_at_1mm();
  expect_agreement(phantom, separate_jaws(segment_tissues(phantom.ct), phantom.landmarks));
}

// A CT whose molar crowns were not found (metal streaks; a posterior arch without teeth): the
// occlusal plane comes from the palate (ANS-PNS at the adults' mean tilt) and the arches end at
// PNS. On the phantom that still tells the jaws apart.
TEST(JawSeparation, WithoutFirstMolarsThePalateGivesTheOcclusalPlane) {
  const auto phantom = phantom_at_1mm();
  LandmarkSet without_molars;
  for (const auto& l : phantom.landmarks)
    if (!l.label.starts_with("U6") && !l.label.starts_with("L6")) without_molars.push_back(l);
  ASSERT_EQ(without_molars.size() + 4, phantom.landmarks.size());
  expect_agreement(phantom, separate_jaws(segment_tissues(phantom.ct), without_molars));
  // Without the palate either, the error names what is missing.
  LandmarkSet no_palate;
  for (const auto& l : without_molars)
    if (l.label != "PNS") no_palate.push_back(l);
  try {
    separate_jaws(segment_tissues(phantom.ct), no_palate);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("U6R or L6R, or ANS and PNS"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace maxillo::planning
