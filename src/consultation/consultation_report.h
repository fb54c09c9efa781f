#pragma once
// The consultation report of one case: patient and imaging, the 3D views of skin and bone, the
// sections of what the archive keeps of the case (cephalometry and follow-up, the newest plan
// result, occlusion, face prediction and validation) and the case's contents, laid out from
// templates/consultation.json and stored back in the archive as a "report" artefact.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "archive/archive.h"
#include "casework/surfaces/case_surfaces.h"
#include "casework/surfaces/case_views.h"
#include "report/report_model.h"

namespace maxillo::consultation {

struct ConsultationOptions {
  std::string template_resource = "templates/consultation.json";
  casework::SurfaceRecipe surfaces;
  casework::ViewRecipe views;
};

struct ConsultationResult {
  std::filesystem::path pdf;
  std::string report_sha256;  // the stored copy in the archive
  int pages = 0;
  bool surfaces_reused = false;
  double seconds_surfaces = 0;
  double seconds_views = 0;
  double seconds_layout = 0;
};

// Writes the report to out_pdf (atomically). Throws Error naming what could not be done.
ConsultationResult write_consultation_report(Archive& archive, int64_t case_id, const std::filesystem::path& out_pdf,
                                             const ConsultationOptions& options = {});

}  // namespace maxillo::consultation
