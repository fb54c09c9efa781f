#pragma once
// What `maxillo serve` accepts over the network: the storage SOP classes a head CT, a cone-beam
// CT, an MR or a report arrive in, each with the transfer syntaxes the archive's slice reader can
// decode (dicom/dicom_slice_reader.h). A peer proposing anything else is refused at association
// negotiation for that presentation context, which DCMTK logs with the reason.
#include <string>
#include <vector>

namespace maxillo::net {

struct StorageClass {
  std::string sop_class_uid;
  std::string name;
};

// CT, enhanced CT, cone-beam (X-Ray 3D Craniofacial), MR, enhanced MR, secondary capture (single
// and multi-frame) and Encapsulated PDF (reports sent back by other systems).
const std::vector<StorageClass>& accepted_storage_classes();

// Preferred first: uncompressed (explicit little endian, implicit little endian, deflated,
// explicit big endian), then the compressed syntaxes the reader decodes (JPEG baseline, extended,
// lossless; JPEG-LS lossless and near-lossless; RLE), so a compressed study is kept as sent.
const std::vector<std::string>& accepted_transfer_syntaxes();

}  // namespace maxillo::net
