#pragma once
// Internal to src/net: the presentation contexts a storage SCP of ours accepts.
#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/scpcfg.h>

namespace maxillo::net {

// C-ECHO (DCMTK's DcmStorageSCP adds its own).
void accept_verification(DcmSCPConfig& config);
// Every class of net/storage_classes.h in every transfer syntax it lists.
void accept_storage(DcmSCPConfig& config);

}  // namespace maxillo::net
