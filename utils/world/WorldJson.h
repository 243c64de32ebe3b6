#pragma once

// The world file (doc/world-format.md): JSON in, JSON out, one reader and one
// writer for every part (the programs, the launcher, the engine adapters).

#include <stdexcept>
#include <string>

#include "WorldDescription.h"

namespace odelab::world {

// A world file that cannot be used, with what and where: "bodies[3].mass:
// must be > 0, got -1". Nothing has been built when it is thrown.
class WorldFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  // `field` is the path the message starts with, so that the reader can add its line.
  WorldFileError(const std::string& field, const std::string& what) : std::runtime_error(field + ": " + what), field_(field) {}
  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

// Something in a world file that runs but is likely not what its author meant
// (bodies overlapping at t = 0), said on stderr before the run.
struct WorldWarning {
  std::string field;
  std::string what;
};

World worldFromJson(const std::string& text);  // throws WorldFileError
std::string worldToJson(const World& world);   // removed bodies left out, indices renumbered
World readWorldFile(const std::string& path);  // throws WorldFileError naming the path

}  // namespace odelab::world
