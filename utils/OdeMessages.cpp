#include "OdeMessages.h"

#include <ode/ode.h>

#include <chrono>
#include <cstdarg>
#include <cstdio>
#include <iostream>

namespace odelab {

namespace {

constexpr int MESSAGES_PER_SECOND = 5;
constexpr size_t RECENT_KEPT = 4;

std::deque<std::string> recentMessages;
long suppressed = 0;
int printedThisSecond = 0;
std::chrono::steady_clock::time_point windowStart;

std::string format(int number, const char* fmt, va_list args) {
  char buffer[1024];
  std::vsnprintf(buffer, sizeof buffer, fmt, args);
  return "ODE " + std::to_string(number) + ": " + buffer;
}

void onError(int number, const char* fmt, va_list args) { throw OdeError("error: " + format(number, fmt, args)); }

void onDebug(int number, const char* fmt, va_list args) {
  throw OdeError("internal check failed: " + format(number, fmt, args));
}

void onMessage(int number, const char* fmt, va_list args) {
  char buffer[1024];
  std::vsnprintf(buffer, sizeof buffer, fmt, args);
  OdeMessages::handleMessage(number, buffer);
}

}  // namespace

void OdeMessages::install() {
  dSetErrorHandler(onError);
  dSetDebugHandler(onDebug);
  dSetMessageHandler(onMessage);
}

void OdeMessages::handleMessage(int number, const std::string& text) {
  const std::string line = "ODE message " + std::to_string(number) + ": " + text;
  recentMessages.push_back(line);
  while (recentMessages.size() > RECENT_KEPT) recentMessages.pop_front();

  const auto now = std::chrono::steady_clock::now();
  if (now - windowStart >= std::chrono::seconds(1)) {
    if (suppressed > 0) std::cerr << "(" << suppressed << " more ODE messages suppressed)\n";
    suppressed = 0;
    printedThisSecond = 0;
    windowStart = now;
  }
  if (printedThisSecond < MESSAGES_PER_SECOND) {
    ++printedThisSecond;
    std::cerr << line << '\n';
  } else {
    ++suppressed;
  }
}

const std::deque<std::string>& OdeMessages::recent() { return recentMessages; }
long OdeMessages::suppressedCount() { return suppressed; }
void OdeMessages::clear() {
  recentMessages.clear();
  suppressed = 0;
  printedThisSecond = 0;
}

}  // namespace odelab
