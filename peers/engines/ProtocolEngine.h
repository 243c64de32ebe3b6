#pragma once

// An engine on the other side of doc/engine-protocol.md: the world goes
// over as JSON, each step comes back as every body's state. Havok, Jolt and
// Rapier are reached this way, in a Node.js child process (NodeEngine.cpp)
// or, in the browser build, in the page itself (BrowserEngine.cpp); the link
// is all that differs.

#include <cstddef>
#include <memory>
#include <string>

#include "world/Engine.h"

namespace odelab::engines {

// Lines to and from the engine's side.
class ProtocolLink {
 public:
  virtual ~ProtocolLink() = default;
  // false when the other side no longer takes messages.
  virtual bool writeLine(const std::string& line) = 0;
  // The reply to the last message that takes one; false when there is none.
  virtual bool readLine(std::string& line) = 0;
  // After a failed write or read: how the other side ended, in words.
  virtual std::string endedHow() = 0;
  // The next message and its reply must be done within `seconds` (the page
  // answers at once, within the call: it has none).
  virtual void setDeadline(double seconds) { (void)seconds; }
};

// How long the other side may take over one message, scaled to the work it
// asks for (doc/engine-protocol.md, "Deadlines"): `bodies` is the number of
// bodies, geoms and joints the message carries or the world holds, `steps`
// the steps it asks for (0 for a message that steps nothing). A build
// includes starting Node.js and compiling the engine's WebAssembly.
double requestDeadlineSeconds(const std::string& op, std::size_t bodies, long steps);

// `title` names the engine in messages ("Jolt"), `where` its side ("Node.js
// engine server"). Sends quit when destroyed.
std::unique_ptr<world::Engine> makeProtocolEngine(const std::string& title, const std::string& where,
                                                  std::unique_ptr<ProtocolLink> link);

}  // namespace odelab::engines
