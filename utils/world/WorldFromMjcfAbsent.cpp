// The MJCF reader of a build without MuJoCo (libmujoco-dev was not found at
// configure): the file is recognised and refused, rather than read as JSON
// and refused for a syntax it never had.
#include "WorldFromMjcf.h"
#include "WorldJson.h"

namespace odelab::world {

World worldFromMjcf(const std::string& path) {
  throw WorldFileError(path + ": MJCF needs MuJoCo (libmujoco-dev); this build has none");
}

}  // namespace odelab::world
