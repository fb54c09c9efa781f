#pragma once
// Skin that lines a cavity: the inside of the lips where they meet, the nostrils and the nasal
// airway behind them (a CT's skin surface follows the air inwards wherever it is open to the
// outside), folds. A prediction is judged on the outer face, which a camera or a hand sees;
// cavity linings are imaged poorly, and a prediction that lets the lips pass into each other
// makes them meaningless.
//
// A vertex lines a cavity when the ray from it along its outward normal enters the skin again
// within `reach_mm`: on the outer face it leaves into open air. The ray is marched by the
// distance to the nearest surface (sphere tracing), so open air costs few queries.
#include <vector>

#include "core/triangle_mesh.h"

namespace maxillo::validation {

struct CavityOptions {
  double reach_mm = 150;        // how far along the normal to look (out of any head)
  double step_mm = 0.5;         // smallest step along the ray (thinner walls than this may be missed)
  double probe_radius_mm = 20;  // distance queries look this far; farther means open air
};

// true where the vertex lines a cavity; only vertices with include[i] are tested (all when
// empty), the others are false. `skin`: closed and outward-oriented.
std::vector<bool> cavity_vertices(const TriangleMesh& skin, const std::vector<bool>& include = {},
                                  const CavityOptions& options = {});

}  // namespace maxillo::validation
