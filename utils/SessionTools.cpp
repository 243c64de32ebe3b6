#include "SessionTools.h"

#include <iostream>

namespace odelab {

namespace {
constexpr double NOTICE_SECONDS = 4.0;
}

void SessionTools::notify(const std::string& message) {
  std::cerr << message << '\n';
  notice_ = message;
  noticeUntil_ = time_.sessionWallSeconds() + NOTICE_SECONDS;
}

std::string SessionTools::notice() const {
  return time_.sessionWallSeconds() < noticeUntil_ ? notice_ : std::string();
}

bool SessionTools::takeScreenshotRequest() {
  const bool requested = screenshotRequested_;
  screenshotRequested_ = false;
  return requested;
}

}  // namespace odelab
