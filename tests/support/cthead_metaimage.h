#pragma once
// The real cadaver head's raw slices (../shared/data/cthead-stanford/slices) as a MetaImage
// header, as they are: identity direction, no HU offset, slice 1 (the vertex) first.
#include <filesystem>
#include <fstream>

namespace maxillo::testing {

inline std::filesystem::path cthead_slices() {
  return std::filesystem::path(MAXILLO_SHARED_DATA) / "cthead-stanford" / "slices";
}

// Writes FOLDER/NAME pointing at the slices; returns its path.
inline std::filesystem::path write_cthead_metaimage(const std::filesystem::path& folder,
                                                    const std::string& name = "cthead.mhd") {
  std::ofstream(folder / name) << "ObjectType = Image\nNDims = 3\nDimSize = 256 256 113\nElementType = MET_USHORT\n"
                                  "ElementSpacing = 1.0 1.0 2.0\nElementByteOrderMSB = True\nOffset = 0 0 0\n"
                                  "ElementDataFile = "
                               << std::filesystem::absolute(cthead_slices()).string() << "/CThead.%d 1 113 1\n";
  return folder / name;
}

}  // namespace maxillo::testing
