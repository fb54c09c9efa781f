#pragma once
// "A separately converted copy of the same volume" (issue 14, defect 12) for registration tests:
// the same HU written the way another converter might write them, as a real MetaImage file read
// back with read_volume_file. The copy differs from the original in
//   - pixel type and rescale: float pixels holding HU + 1024, read back with hu_offset -1024;
//   - storage order: slices top-down (the k axis reversed, the origin at the other end);
//   - origin convention: the world moved by `origin_shift` mm (e.g. half a voxel: a corner
//     rather than a centre convention); a point p of the original is p + origin_shift in the copy;
//   - padding: air (HU <= -1000) at the image's x border set to padding_hu (what scanners write
//     outside the reconstructed field of view); the anatomy's HU stay the same.
#include <filesystem>
#include <fstream>
#include <string>

#include "core/volume.h"
#include "imaging/volume_file.h"

namespace maxillo::testing {

struct CopyConversion {
  Eigen::Vector3d origin_shift = Eigen::Vector3d::Zero();
  int16_t padding_hu = -3024;
};

inline Volume converted_copy(const Volume& ct, const std::filesystem::path& folder, const std::string& name,
                             const CopyConversion& conversion = {}) {
  const VolumeGeometry& g = ct.geometry;
  const Eigen::Vector3d top = g.world(Eigen::Vector3d(0, 0, g.size.z() - 1)) + conversion.origin_shift;
  Eigen::Matrix3d direction = g.direction;
  direction.col(2) = -direction.col(2);
  {
    std::ofstream raw(folder / (name + ".raw"), std::ios::binary);
    for (int k = g.size.z() - 1; k >= 0; --k)
      for (int j = 0; j < g.size.y(); ++j)
        for (int i = 0; i < g.size.x(); ++i) {
          const bool border_air = (i < 2 || i >= g.size.x() - 2) && ct.at(i, j, k) <= -1000;
          const float stored = float((border_air ? conversion.padding_hu : ct.at(i, j, k)) + 1024);
          raw.write(reinterpret_cast<const char*>(&stored), sizeof stored);
        }
  }
  std::ofstream header(folder / (name + ".mhd"));
  header.precision(17);
  header << "ObjectType = Image\nNDims = 3\nDimSize = " << g.size.x() << " " << g.size.y() << " " << g.size.z()
         << "\nElementType = MET_FLOAT\nElementSpacing = " << g.spacing.x() << " " << g.spacing.y() << " "
         << g.spacing.z() << "\nOffset = " << top.x() << " " << top.y() << " " << top.z() << "\nTransformMatrix =";
  for (int axis = 0; axis < 3; ++axis)
    for (int r = 0; r < 3; ++r) header << " " << direction(r, axis);  // one axis after the other
  header << "\nElementByteOrderMSB = False\nElementDataFile = " << name << ".raw\n";
  header.close();
  return read_volume_file(folder / (name + ".mhd"), {.hu_offset = -1024});
}

}  // namespace maxillo::testing
