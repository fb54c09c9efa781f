#include "softtissue/local_iteration.h"

#include <algorithm>
#include <cassert>

namespace maxillo::softtissue {

Precision precision_against(const Eigen::MatrixX3d& displacement, const Eigen::MatrixX3d& converged,
                            const Eigen::VectorX<bool>& is_free) {
  assert(displacement.rows() == converged.rows() && displacement.rows() == is_free.size() &&
         "precision_against: sizes differ");
  Precision precision;
  int count = 0;
  for (Eigen::Index i = 0; i < displacement.rows(); ++i) {
    if (!is_free(i)) continue;
    double distance = (displacement.row(i) - converged.row(i)).norm();
    precision.worst_mm = std::max(precision.worst_mm, distance);
    precision.mean_mm += distance;
    ++count;
  }
  if (count > 0) precision.mean_mm /= count;
  return precision;
}

}  // namespace maxillo::softtissue
