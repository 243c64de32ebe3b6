#pragma once

#include <stdexcept>

namespace odelab {

// A failure in setting up or drawing the window (shader, font, file): its own
// type so runWindow can report it without also catching odelab::OdeError,
// which must reach the caller to be mapped to its exit status.
class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A shader or font that was found but cannot be used (unreadable, not
// GLSL that compiles and links, not a font): like one not found, a resource
// problem, exit_code::MISSING_RESOURCE. The message names the file.
class ResourceError : public RenderError {
 public:
  using RenderError::RenderError;
};

}  // namespace odelab
