#pragma once
// The "dental" section of the consultation report (issue 30): the patient's dental scans placed
// into the CT. The augmented model (the CT's teeth with the scanned crowns in their place, the
// crowns coloured apart) from the front and the right; each arch's fit pictured from its occlusal side, coloured by each scan point's
// distance to the CT's teeth, and a table of the fits: how much of the scan lies on the teeth,
// the RMS and P95 distance of that part, the share within 0.3 mm, the confidence (how far the
// best other pose falls short) and where the search started. Import warnings and arches whose
// newest scan is not registered yet are noted.
#include <optional>
#include <vector>

#include "records/dental_scans.h"
#include "report/report_model.h"

namespace maxillo::sections {

// nullopt when the case has no dental scans.
std::optional<report::Section> dental_section(const records::CaseDentalScans& dental);

}  // namespace maxillo::sections
