#include "core/error.h"

#include <array>

namespace maxillo {
namespace {

struct CatalogueEntry {
  ErrorCode code;
  int exit_code;
  std::string_view name;
  std::string_view description;
};

constexpr std::array kCatalogue = {
#define MAXILLO_ERROR(name, exit_code, description) \
  CatalogueEntry{ErrorCode::name, exit_code, std::string_view(#name).substr(1), description},
#include "core/error_catalogue.def"
#undef MAXILLO_ERROR
};

const CatalogueEntry& entry(ErrorCode code) { return kCatalogue[static_cast<size_t>(code)]; }

std::string format_message(const std::string& subject, const std::string& reason) {
  return subject.empty() ? reason : subject + ": " + reason;
}

}  // namespace

int exit_code_for(ErrorCode code) { return entry(code).exit_code; }
std::string_view describe(ErrorCode code) { return entry(code).description; }
std::string_view name_of(ErrorCode code) { return entry(code).name; }

Error::Error(ErrorCode code, std::string subject, std::string reason)
    : std::runtime_error(format_message(subject, reason)),
      code_(code),
      subject_(std::move(subject)),
      reason_(std::move(reason)) {}

}  // namespace maxillo
