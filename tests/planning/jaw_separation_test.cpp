// Telling the jaws apart on a CT segmentation: on the phantom's CT the result must agree with
// the phantom's own labels (its construction is the known answer).
#include <gtest/gtest.h>

#include <map>

#include "imaging/segmentation.h"
#include "planning/jaw_separation.h"
#include "sample/phantom.h"

namespace maxillo::planning {
namespace {

TEST(JawSeparation, AgreesWithThePhantomsOwnLabels) {
  PhantomSpec spec;
  spec.spacing_mm = 1.0;
  const auto phantom = make_phantom(spec);
  const auto separated = separate_jaws(segment_tissues(phantom.ct), phantom.landmarks);
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

}  // namespace
}  // namespace maxillo::planning
