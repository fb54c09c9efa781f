#include "casework/surfaces/case_tissues.h"

#include "core/log.h"
#include "imaging/hounsfield_reading.h"
#include "imaging/segmentation.h"
#include "imaging/volume_assembly.h"
#include "records/archived_series.h"
#include "records/derivation.h"
#include "planning/enclosed_air.h"
#include "planning/jaw_separation.h"

namespace maxillo::casework {

CaseTissues load_case_tissues(Archive& archive, int64_t case_id, const LandmarkSet& landmarks) {
  const int64_t series = records::primary_series(archive.case_contents(case_id));
  return segment_case_tissues(records::load_archived_series(archive, series), landmarks);
}

CaseTissues segment_case_tissues(const Volume& scan, const LandmarkSet& landmarks) {
  log::info("segmenting the CT (soft tissue, sinus air, bone, teeth, jaws)");
  // The thresholds are in HU: a cone-beam scan is read as HU first (hounsfield_reading.h).
  const std::optional<Volume> converted = in_hounsfield_units(scan);
  const Volume& ct = converted ? *converted : scan;
  const SegmentationOptions segmentation;
  CaseTissues tissues;
  tissues.ct_labels = segment_tissues(ct, segmentation);
  tissues.segmentation = planning::with_enclosed_air(tissues.ct_labels, ct, segmentation.skin_hu, kEnclosedAir);
  tissues.jaws = planning::separate_jaws(tissues.segmentation, landmarks);
  return tissues;
}

}  // namespace maxillo::casework
