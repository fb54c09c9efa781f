#pragma once
// In-memory DICOM slices and volumes with known geometry and values, for assembly tests.
#include <Eigen/Geometry>

#include <cmath>
#include <string>
#include <vector>

#include "core/volume.h"
#include "dicom/dicom_slice_reader.h"
#include "support/oblique_axes.h"

namespace maxillo::testing {

// HU that identifies a voxel: distinct for every (column, row, slice position).
inline int16_t marker_hu(int column, int row, double along_mm) {
  return int16_t(column + 40 * row + std::lround(10 * along_mm) % 1000);
}

// One slice of `columns` x `rows` whose first pixel sits at `position`; pixel values are
// marker_hu of their column, row and `along_mm`.
inline DicomSlice make_slice(const std::string& name, const Eigen::Vector3d& position, double along_mm,
                             const Eigen::Matrix3d& axes = Eigen::Matrix3d::Identity(), int columns = 6, int rows = 5) {
  DicomSlice s;
  s.path = name;
  s.series_instance_uid = "1.2.3";
  s.sop_instance_uid = "1.2.3." + name;
  s.position = position;
  s.row_direction = axes.col(0);
  s.column_direction = axes.col(1);
  s.row_spacing = 0.8;
  s.column_spacing = 0.6;
  s.rows = rows;
  s.columns = columns;
  s.hu.resize(size_t(rows) * columns);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) s.hu[size_t(c + columns * r)] = marker_hu(c, r, along_mm);
  return s;
}

// n slices at the given positions along the normal of `axes` (third column), origin `start`.
inline std::vector<DicomSlice> make_stack(const std::vector<double>& along,
                                          const Eigen::Matrix3d& axes = Eigen::Matrix3d::Identity(),
                                          const Eigen::Vector3d& start = {10, -20, 30}) {
  std::vector<DicomSlice> slices;
  for (size_t k = 0; k < along.size(); ++k)
    slices.push_back(make_slice("slice" + std::to_string(k) + ".dcm", start + axes.col(2) * along[k], along[k], axes));
  return slices;
}

}  // namespace maxillo::testing
