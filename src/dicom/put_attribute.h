#pragma once
// A text attribute put into a DCMTK data set, shared by the module's writers (the CT series, the
// Encapsulated PDF). Private to the dicom module: it speaks DCMTK's types. DCMTK refuses only a
// tag that takes no text, which is a mistake in our code, not in the input: hence an assert.
#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdatset.h>

#include <cassert>
#include <string>

namespace maxillo {

inline void put(DcmDataset& dataset, const DcmTagKey& tag, const std::string& value) {
  [[maybe_unused]] OFCondition status = dataset.putAndInsertString(tag, value.c_str());
  assert(status.good() && "cannot insert a DICOM attribute");
}

}  // namespace maxillo
