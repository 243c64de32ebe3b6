// The SDF reader of a build without SDFormat (libsdformat-dev was not found
// at configure): the file is recognised and refused, rather than read as
// JSON and refused for a syntax it never had.
#include "WorldFromSdf.h"
#include "WorldJson.h"

namespace odelab::world {

World worldFromSdf(const std::string& path) {
  throw WorldFileError(path + ": SDF needs SDFormat (libsdformat-dev); this build has none");
}

}  // namespace odelab::world
