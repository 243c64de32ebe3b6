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
constexpr auto RECENT_SHOWN_FOR = std::chrono::seconds(5);

struct TimedMessage {
  std::chrono::steady_clock::time_point when;
  std::string text;
};
std::deque<TimedMessage> recentMessages;
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
  const auto now = std::chrono::steady_clock::now();
  recentMessages.push_back({now, line});
  while (recentMessages.size() > RECENT_KEPT) recentMessages.pop_front();

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

std::deque<std::string> OdeMessages::recent() {
  std::deque<std::string> lines;
  const auto oldest = std::chrono::steady_clock::now() - RECENT_SHOWN_FOR;
  for (const auto& message : recentMessages)
    if (message.when >= oldest) lines.push_back(message.text);
  return lines;
}
long OdeMessages::suppressedCount() { return suppressed; }
void OdeMessages::clear() {
  recentMessages.clear();
  suppressed = 0;
  printedThisSecond = 0;
}

}  // namespace odelab
