#include "net/storage_contexts.h"

#include <dcmtk/dcmdata/dcuid.h>

#include "net/storage_classes.h"

namespace maxillo::net {

void accept_verification(DcmSCPConfig& config) {
  OFList<OFString> syntaxes;
  syntaxes.push_back(UID_LittleEndianExplicitTransferSyntax);
  syntaxes.push_back(UID_LittleEndianImplicitTransferSyntax);
  config.addPresentationContext(UID_VerificationSOPClass, syntaxes);
}

void accept_storage(DcmSCPConfig& config) {
  OFList<OFString> syntaxes;
  for (const auto& uid : accepted_transfer_syntaxes()) syntaxes.push_back(uid.c_str());
  for (const auto& storage : accepted_storage_classes()) config.addPresentationContext(storage.sop_class_uid.c_str(), syntaxes);
}

}  // namespace maxillo::net
