#pragma once
// Where each landmark is expected before it is looked for: an adult Class I head set straight
// (Frankfort horizontal, midsagittal plane x = 0), relative to sella, for an S-N length of
// 70 mm. The rules search windows around these positions scaled to the scan's own S-N, and read
// the anatomy there; the template never becomes a landmark itself. The values are those of the
// phantom's design (src/sample/phantom_design.h), which follows adult norms: SNA 82, SNB 80,
// S-N 7 degrees to Frankfort, ANS-Me 68 mm.
#include <string>
#include <vector>

#include <Eigen/Core>

namespace maxillo::landmarking {

// Mean mesio-distal crown widths of the central incisors (mm): the upper about 8.5, the lower
// about 5.2 (Moyers' adult norms). L1 and U1 lie half a width from the arch's midline.
inline constexpr double kUpperCentralWidthMm = 8.5, kLowerCentralWidthMm = 5.2;

// The 29 labels the program uses, in the order they are reported.
const std::vector<std::string>& detected_labels();

// The expected position (frame mm, relative to S) scaled by `scale` = S-N / 70 mm. Bilateral
// labels (R/L suffix) lie on their side (patient right = -x).
Eigen::Vector3d expected_position(const std::string& label, double scale);

}  // namespace maxillo::landmarking
