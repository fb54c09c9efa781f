#include "net/storage_contexts.h"

#include <dcmtk/dcmdata/dcuid.h>

#include <algorithm>

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
  for (const auto& storage : accepted_storage_classes())
    config.addPresentationContext(storage.sop_class_uid.c_str(), syntaxes);
}

namespace {

std::string name_of_uid(const char* uid) {
  const char* name = dcmFindNameOfUID(uid, nullptr);
  return name != nullptr ? name : uid;
}

bool accepted_class(const std::string& uid) {
  if (uid == UID_VerificationSOPClass) return true;
  const auto& classes = accepted_storage_classes();
  return std::any_of(classes.begin(), classes.end(), [&](const auto& c) { return c.sop_class_uid == uid; });
}

bool accepted_syntax(const std::string& abstract_syntax, const std::string& uid) {
  if (abstract_syntax == UID_VerificationSOPClass)
    return uid == UID_LittleEndianExplicitTransferSyntax || uid == UID_LittleEndianImplicitTransferSyntax;
  const auto& syntaxes = accepted_transfer_syntaxes();
  return std::find(syntaxes.begin(), syntaxes.end(), uid) != syntaxes.end();
}

}  // namespace

std::vector<std::string> refused_contexts(const T_ASC_Parameters& request) {
  // ASC_getPresentationContext only reads, but takes a non-const pointer.
  auto* params = const_cast<T_ASC_Parameters*>(&request);
  std::vector<std::string> refusals;
  for (int i = 0; i < ASC_countPresentationContexts(params); ++i) {
    T_ASC_PresentationContext context{};
    if (ASC_getPresentationContext(params, i, &context).bad()) continue;
    const std::string abstract_syntax = context.abstractSyntax;
    if (!accepted_class(abstract_syntax)) {
      refusals.push_back(name_of_uid(context.abstractSyntax) + ": not a class we store");
      continue;
    }
    bool any = false;
    std::string proposed;
    for (int s = 0; s < context.transferSyntaxCount; ++s) {
      any |= accepted_syntax(abstract_syntax, context.proposedTransferSyntaxes[s]);
      proposed += (s ? ", " : "") + name_of_uid(context.proposedTransferSyntaxes[s]);
    }
    if (!any)
      refusals.push_back(name_of_uid(context.abstractSyntax) + ": no transfer syntax we decode among " + proposed);
  }
  return refusals;
}

}  // namespace maxillo::net
