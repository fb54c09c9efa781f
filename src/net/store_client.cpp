#include "net/store_client.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcmetinf.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmnet/diutil.h>

#include <chrono>
#include <map>
#include <set>

#include "core/error.h"
#include "net/association_requestor.h"
#include "net/tls_layer.h"

namespace maxillo::net {
namespace {

struct FileSyntax {
  std::string sop_class_uid;
  std::string transfer_syntax_uid;
};

// The SOP class and transfer syntax a file declares in its meta header (only the header is read).
FileSyntax file_syntax(const std::filesystem::path& file) {
  DcmFileFormat format;
  const OFCondition read = format.loadFile(file.c_str(), EXS_Unknown, EGL_noChange, DCM_MaxReadLength, ERM_metaOnly);
  OFString sop_class, syntax;
  if (read.bad() || format.getMetaInfo()->findAndGetOFString(DCM_MediaStorageSOPClassUID, sop_class).bad() ||
      format.getMetaInfo()->findAndGetOFString(DCM_TransferSyntaxUID, syntax).bad())
    throw Error(ErrorCode::kNotDicom, file.string(), "no DICOM meta header with a SOP class and a transfer syntax");
  return {sop_class.c_str(), syntax.c_str()};
}

bool is_uncompressed(const std::string& syntax) {
  return syntax == UID_LittleEndianExplicitTransferSyntax || syntax == UID_LittleEndianImplicitTransferSyntax ||
         syntax == UID_BigEndianExplicitTransferSyntax;
}

// One presentation context per SOP class and stored transfer syntax. Only the stored syntax is
// proposed, so what the peer receives is what the archive holds (an uncompressed file is also
// offered as implicit little endian, which every SCP must accept).
void propose(DcmSCU& scu, const std::set<std::pair<std::string, std::string>>& pairs) {
  for (const auto& [sop_class, syntax] : pairs) {
    OFList<OFString> syntaxes;
    syntaxes.push_back(syntax.c_str());
    if (is_uncompressed(syntax) && syntax != UID_LittleEndianImplicitTransferSyntax)
      syntaxes.push_back(UID_LittleEndianImplicitTransferSyntax);
    scu.addPresentationContext(sop_class.c_str(), syntaxes);
  }
}

std::string status_text(Uint16 status) {
  char hex[8];
  std::snprintf(hex, sizeof hex, "0x%04x", status);
  return std::string("status ") + hex + " (" + DU_cstoreStatusString(status) + ")";
}

}  // namespace

StoreReport send_files(const DicomPeer& peer, const std::vector<std::filesystem::path>& files,
                       const StoreOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  std::vector<FileSyntax> syntaxes;
  std::set<std::pair<std::string, std::string>> pairs;
  for (const auto& file : files) {
    syntaxes.push_back(file_syntax(file));
    pairs.emplace(syntaxes.back().sop_class_uid, syntaxes.back().transfer_syntax_uid);
  }
  StoreReport report;
  if (files.empty()) return report;
  if (pairs.size() > 128)
    throw Error(ErrorCode::kUsage, to_string(peer),
                "more than 128 SOP class and transfer syntax pairs for one association");

  const auto tls = requestor_tls(options.tls);  // outlives the association
  Requestor scu;
  configure_requestor(scu, peer, options.calling_ae, options.timeout_seconds, tls.get());
  propose(scu, pairs);
  request_association(scu, peer);

  Progress progress("send", files.size(), options.progress);
  for (size_t i = 0; i < files.size(); ++i) {
    const auto& [sop_class, syntax] = syntaxes[i];
    const T_ASC_PresentationContextID context = scu.findAnyPresentationContextID(sop_class.c_str(), syntax.c_str());
    progress.advance();
    if (context == 0) {
      report.failures.push_back({files[i], "the peer accepted no presentation context for SOP class " + sop_class +
                                               " in transfer syntax " + syntax});
      continue;
    }
    Uint16 status = 0;
    const OFCondition sent = scu.sendSTORERequest(context, files[i].c_str(), nullptr, status);
    if (sent.bad()) {
      report.failures.push_back({files[i], std::string("not sent: ") + sent.text()});
      if (!scu.isConnected()) {  // the association is gone: the rest cannot be sent either
        for (size_t rest = i + 1; rest < files.size(); ++rest)
          report.failures.push_back({files[rest], "not sent: the association ended"});
        break;
      }
      continue;
    }
    // Success (0x0000) and warnings (0xB...) mean the peer kept the instance.
    if (status == STATUS_Success || (status & 0xf000) == 0xb000)
      ++report.sent;
    else
      report.failures.push_back({files[i], "refused by the peer: " + status_text(status)});
  }
  progress.finish();
  if (scu.isConnected()) scu.releaseAssociation();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return report;
}

}  // namespace maxillo::net
