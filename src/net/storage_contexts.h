#pragma once
// Internal to src/net: the presentation contexts a storage SCP of ours accepts.
#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/assoc.h>
#include <dcmtk/dcmnet/scpcfg.h>

#include <string>
#include <vector>

namespace maxillo::net {

// C-ECHO (DCMTK's DcmStorageSCP adds its own).
void accept_verification(DcmSCPConfig& config);
// Every class of net/storage_classes.h in every transfer syntax it lists.
void accept_storage(DcmSCPConfig& config);

// For the log: why each presentation context that `request` proposes will be refused by the
// two above, e.g. "RT Plan Storage: not a class we store"; empty when all are acceptable.
std::vector<std::string> refused_contexts(const T_ASC_Parameters& request);

}  // namespace maxillo::net
