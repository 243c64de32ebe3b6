// Which reader a world file goes to: MJCF (WorldFromMjcf.h) or this
// format's JSON (WorldJson.cpp). Both builds, with MuJoCo and without, use
// the same test, so that an MJCF file is named as such either way.
#include <cstring>

#include "WorldFromMjcf.h"

namespace odelab::world {

bool looksLikeMjcf(const std::string& path, const std::string& text) {
  const std::string xml = ".xml";
  if (path.size() >= xml.size() && path.compare(path.size() - xml.size(), xml.size(), xml) == 0) return true;
  size_t at = 0;
  const auto skipBlanks = [&] { while (at < text.size() && std::strchr(" \t\r\n", text[at]) && text[at]) ++at; };
  skipBlanks();
  if (text.compare(at, 5, "<?xml") == 0) {
    const size_t end = text.find("?>", at);
    if (end == std::string::npos) return false;
    at = end + 2;
    skipBlanks();
  }
  return text.compare(at, 7, "<mujoco") == 0;
}

}  // namespace odelab::world
