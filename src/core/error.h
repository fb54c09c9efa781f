#pragma once
// Recoverable errors: bad input, I/O, archive problems. Each carries a code from
// error_catalogue.def, the file or item it concerns, and a reason a person can act on.
// Misuse of an API is not an Error: it is an assert with a message.
#include <stdexcept>
#include <string>
#include <string_view>

namespace maxillo {

enum class ErrorCode {
#define MAXILLO_ERROR(name, exit_code, description) name,
#include "core/error_catalogue.def"
#undef MAXILLO_ERROR
};

// Process exit code reserved for this kind of error (see error_catalogue.def).
int exit_code_for(ErrorCode code);
// Short description of the kind, e.g. "not a DICOM file".
std::string_view describe(ErrorCode code);
// The enumerator's name without the leading k, e.g. "NotDicom" (for --json output).
std::string_view name_of(ErrorCode code);

class Error : public std::runtime_error {
 public:
  // subject: the file path, UID or item the error is about (may be empty).
  Error(ErrorCode code, std::string subject, std::string reason);
  ErrorCode code() const { return code_; }
  const std::string& subject() const { return subject_; }
  const std::string& reason() const { return reason_; }

 private:
  ErrorCode code_;
  std::string subject_;
  std::string reason_;
};

}  // namespace maxillo
