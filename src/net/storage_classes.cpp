#include "net/storage_classes.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcuid.h>

namespace maxillo::net {

const std::vector<StorageClass>& accepted_storage_classes() {
  static const std::vector<StorageClass> classes = {
      {UID_CTImageStorage, "CT Image"},
      {UID_EnhancedCTImageStorage, "Enhanced CT Image"},
      {UID_XRay3DCraniofacialImageStorage, "X-Ray 3D Craniofacial Image (cone-beam CT)"},
      {UID_MRImageStorage, "MR Image"},
      {UID_EnhancedMRImageStorage, "Enhanced MR Image"},
      {UID_SecondaryCaptureImageStorage, "Secondary Capture Image"},
      {UID_MultiframeGrayscaleByteSecondaryCaptureImageStorage, "Multi-frame Grayscale Byte Secondary Capture"},
      {UID_MultiframeGrayscaleWordSecondaryCaptureImageStorage, "Multi-frame Grayscale Word Secondary Capture"},
      {UID_MultiframeTrueColorSecondaryCaptureImageStorage, "Multi-frame True Color Secondary Capture"},
      {UID_EncapsulatedPDFStorage, "Encapsulated PDF"},
  };
  return classes;
}

const std::vector<std::string>& accepted_transfer_syntaxes() {
  static const std::vector<std::string> syntaxes = {
      UID_LittleEndianExplicitTransferSyntax,
      UID_LittleEndianImplicitTransferSyntax,
      UID_DeflatedExplicitVRLittleEndianTransferSyntax,
      UID_BigEndianExplicitTransferSyntax,
      UID_JPEGProcess1TransferSyntax,
      UID_JPEGProcess2_4TransferSyntax,
      UID_JPEGProcess14TransferSyntax,
      UID_JPEGProcess14SV1TransferSyntax,
      UID_JPEGLSLosslessTransferSyntax,
      UID_JPEGLSLossyTransferSyntax,
      UID_RLELosslessTransferSyntax,
  };
  return syntaxes;
}

}  // namespace maxillo::net
