#include "archive/dicom_pixel_data.h"

#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcpixseq.h>
#include <dcmtk/dcmdata/dcpxitem.h>
#include <dcmtk/dcmdata/dcxfer.h>

namespace maxillo {

bool pixels_are_encapsulated(DcmDataset& dataset) { return DcmXfer(dataset.getOriginalXfer()).isEncapsulated(); }

size_t stored_pixel_bytes(DcmDataset& dataset, DcmPixelData& pixel_data) {
  if (!pixels_are_encapsulated(dataset)) return pixel_data.getLength();
  DcmPixelSequence* fragments = nullptr;
  if (pixel_data.getEncapsulatedRepresentation(dataset.getOriginalXfer(), nullptr, fragments).bad() ||
      fragments == nullptr)
    return 0;
  size_t total = 0;
  for (unsigned long n = 1; n < fragments->card(); ++n) {  // item 0 is the Basic Offset Table
    DcmPixelItem* fragment = nullptr;
    if (fragments->getItem(fragment, n).good() && fragment != nullptr) total += fragment->getLength();
  }
  return total;
}

DcmPixelData* pixel_data_of(DcmDataset& dataset) {
  DcmElement* element = nullptr;
  if (dataset.findAndGetElement(DCM_PixelData, element).bad() || element == nullptr) return nullptr;
  // A damaged VR makes DCMTK read (7FE0,0010) as some other kind of element.
  return dynamic_cast<DcmPixelData*>(element);
}

}  // namespace maxillo
