#include "net/receive_failure_log.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/oflog/appender.h>
#include <dcmtk/oflog/logger.h>
#include <dcmtk/oflog/spi/logevent.h>

namespace maxillo::net {
namespace {

namespace log4 = dcmtk::log4cplus;

// What DcmBaseSCPPool::listen logs when ASC_receiveAssociation fails for a reason other than
// a quiet period (dcmnet/libsrc/scppool.cc).
constexpr const char* kReceiveError = "DcmBaseSCPPool: Error receiving association: ";

class ForwardingAppender final : public log4::Appender {
 public:
  explicit ForwardingAppender(std::function<void(const std::string&)> on_failure)
      : on_failure_(std::move(on_failure)) {}
  ~ForwardingAppender() override { destructorImpl(); }
  void close() override {}

 protected:
  void append(const log4::spi::InternalLoggingEvent& event) override {
    const std::string message = event.getMessage().c_str();
    if (message.rfind(kReceiveError, 0) == 0) on_failure_(message.substr(std::string(kReceiveError).size()));
  }

 private:
  std::function<void(const std::string&)> on_failure_;
};

}  // namespace

struct ReceiveFailureLog::Hook {
  log4::Logger logger = log4::Logger::getInstance("dcmtk.dcmnet");
  log4::SharedAppenderPtr appender;
  log4::LogLevel level_before = log4::NOT_SET_LOG_LEVEL;
  bool additive_before = true;
};

ReceiveFailureLog::ReceiveFailureLog(std::function<void(const std::string&)> on_failure) : hook_(new Hook) {
  hook_->appender = log4::SharedAppenderPtr(new ForwardingAppender(std::move(on_failure)));
  hook_->level_before = hook_->logger.getLogLevel();
  hook_->additive_before = hook_->logger.getAdditivity();
  hook_->logger.addAppender(hook_->appender);
  hook_->logger.setAdditivity(false);  // DCMTK's own console output stays silent
  hook_->logger.setLogLevel(log4::ERROR_LOG_LEVEL);
}

ReceiveFailureLog::~ReceiveFailureLog() {
  hook_->logger.removeAppender(hook_->appender);
  hook_->logger.setAdditivity(hook_->additive_before);
  hook_->logger.setLogLevel(hook_->level_before);
  delete hook_;
}

}  // namespace maxillo::net
