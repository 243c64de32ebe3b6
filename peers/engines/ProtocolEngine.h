#pragma once

// An engine on the other side of doc/engine-protocol.md: the world goes
// over as JSON, each step comes back as every body's state. Havok, Jolt and
// Rapier are reached this way, in a Node.js child process (NodeEngine.cpp)
// or, in the browser build, in the page itself (BrowserEngine.cpp); the link
// is all that differs.

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
};

// `title` names the engine in messages ("Jolt"), `where` its side ("Node.js
// engine server"). Sends quit when destroyed.
std::unique_ptr<world::Engine> makeProtocolEngine(const std::string& title, const std::string& where,
                                                  std::unique_ptr<ProtocolLink> link);

}  // namespace odelab::engines
