#pragma once
// The "soft_tissue" section of the consultation report, from the case's newest stored face
// prediction (records/simulation_archive.h): the pre-operative face and the predicted face side
// by side from the same cameras (frontal, lateral, oblique), the predicted displacement as a
// colour map with a colour bar, the model's facts, the displacement of the soft tissue
// landmarks in the anatomical frame and, when it was computed, the uncertainty band.
#include "records/simulation_archive.h"
#include "report/report_model.h"

namespace maxillo::sections {

// Throws Error(kArchiveCorrupt) naming the artefact when a picture its summary needs is missing.
report::Section soft_tissue_section(const records::StoredSimulation& simulation);

}  // namespace maxillo::sections
