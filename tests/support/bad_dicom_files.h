#pragma once
// Malformed inputs made from a good file with DCMTK: each is one kind of bad input the
// importer must name with its reason.
#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdatset.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcpixel.h>
#include <dcmtk/dcmdata/dcpixseq.h>
#include <dcmtk/dcmdata/dcpxitem.h>

#include <filesystem>
#include <fstream>

namespace maxillo::testing {

inline void write_without(const std::filesystem::path& good, const DcmTagKey& tag, const std::filesystem::path& out) {
  DcmFileFormat file;
  file.loadFile(good.c_str());
  file.getDataset()->findAndDeleteElement(tag);
  file.saveFile(out.c_str(), EXS_LittleEndianExplicit);
}

// A file claiming JPEG 2000 with an encapsulated (fake) codestream: DCMTK has no decoder for it.
inline void write_jpeg2000(const std::filesystem::path& good, const std::filesystem::path& out) {
  DcmFileFormat file;
  file.loadFile(good.c_str());
  DcmDataset* dataset = file.getDataset();
  dataset->findAndDeleteElement(DCM_PixelData);
  auto* sequence = new DcmPixelSequence(DcmTag(DCM_PixelData, EVR_OB));
  sequence->insert(new DcmPixelItem(DcmTag(DCM_Item, EVR_OB)));  // empty offset table
  auto* fragment = new DcmPixelItem(DcmTag(DCM_Item, EVR_OB));
  Uint8 codestream[16] = {0xFF, 0x4F, 0xFF, 0x51, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0xFF, 0xD9};
  fragment->putUint8Array(codestream, sizeof codestream);
  sequence->insert(fragment);
  auto* pixels = new DcmPixelData(DCM_PixelData);
  pixels->putOriginalRepresentation(EXS_JPEG2000LosslessOnly, nullptr, sequence);
  dataset->insert(pixels, true);
  file.saveFile(out.c_str(), EXS_JPEG2000LosslessOnly);
}

inline void write_truncated(const std::filesystem::path& good, const std::filesystem::path& out, double fraction) {
  std::ifstream in(good, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(out, std::ios::binary) << bytes.substr(0, size_t(bytes.size() * fraction));
}

}  // namespace maxillo::testing
