#include "OdeMessages.h"

#include <ode/ode.h>

#include <chrono>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <mutex>
#include <thread>

#include "ExitCodes.h"

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

std::thread::id mainThread;
std::mutex messagesMutex;
// Set by the run (setRunContext): where an error happened, and how to mark
// the output files.
std::function<std::string()> runMoment;
std::function<void(const std::string&)> markRunOutputs;

// An exception cannot leave one of ODE's pool threads (test5 --threads):
// it reaches no handler there and ends the process with std::terminate
// (status 134, no message), and ODE aborts if the handler returns. Such an
// error is reported and ends the program with the status it has on the
// main thread (4); a window cannot pause and replay after it, because the
// pool's other threads and the world are mid-step.
[[noreturn]] void endFromPoolThread(const std::string& message) {
  // The same words as the main thread's error, then where it happened.
  const std::string full = message + (runMoment ? runMoment() : std::string());
  const std::string line = "error: " + full +
                           " (in one of ODE's island-stepping threads, --threads; ODE cannot go on from an error "
                           "there: the run ends. With --threads 1 the window pauses at the last good state)\n";
  try {
    if (markRunOutputs) markRunOutputs("ODE error: " + full);
  } catch (const std::exception& error) {  // a full disk: said, and the run still ends with 4
    std::fprintf(stderr, "error: %s\n", error.what());
  }
  std::fputs(line.c_str(), stderr);
  std::fflush(stderr);
  std::fflush(stdout);
  std::_Exit(exit_code::ODE_ERROR);
}

[[noreturn]] void raise(const std::string& message) {
  if (std::this_thread::get_id() != mainThread) endFromPoolThread(message);
  throw OdeError(message);
}

void onError(int number, const char* fmt, va_list args) { raise("error: " + format(number, fmt, args)); }

void onDebug(int number, const char* fmt, va_list args) { raise("internal check failed: " + format(number, fmt, args)); }

void onMessage(int number, const char* fmt, va_list args) {
  char buffer[1024];
  std::vsnprintf(buffer, sizeof buffer, fmt, args);
  OdeMessages::handleMessage(number, buffer);
}

}  // namespace

void OdeMessages::install() {
  mainThread = std::this_thread::get_id();
  dSetErrorHandler(onError);
  dSetDebugHandler(onDebug);
  dSetMessageHandler(onMessage);
}

void OdeMessages::adoptThread() { mainThread = std::this_thread::get_id(); }

void OdeMessages::setRunContext(std::function<std::string()> moment,
                                std::function<void(const std::string&)> markOutputs) {
  runMoment = std::move(moment);
  markRunOutputs = std::move(markOutputs);
}

void OdeMessages::handleMessage(int number, const std::string& text) {
  // Pool threads (test5 --threads) may report at the same time.
  const std::lock_guard<std::mutex> lock(messagesMutex);
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
  const std::lock_guard<std::mutex> lock(messagesMutex);
  std::deque<std::string> lines;
  const auto oldest = std::chrono::steady_clock::now() - RECENT_SHOWN_FOR;
  for (const auto& message : recentMessages)
    if (message.when >= oldest) lines.push_back(message.text);
  return lines;
}
long OdeMessages::suppressedCount() { return suppressed; }
void OdeMessages::clear() {
  const std::lock_guard<std::mutex> lock(messagesMutex);
  recentMessages.clear();
  suppressed = 0;
  printedThisSecond = 0;
}

}  // namespace odelab
