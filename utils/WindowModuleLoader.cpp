// windowModule() where the window side is a module (Linux): it is looked for
// beside the program (the build tree) and then where an install puts it,
// seen from the program's folder (ODELAB_MODULE_FROM_BINARY, from CMake), as
// /proc/self/exe names the program; loaded once, kept to the end.
#include <dlfcn.h>

#include <iostream>
#include <string>

#include "Platform.h"
#include "WindowModule.h"

namespace odelab {

namespace {

constexpr const char* MODULE_NAME = "odelab_window.so";

std::string folderOf(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

const WindowModule* load() {
  const std::string folder = folderOf(platform::executablePath());
  std::string tried, why;
  for (const std::string& path : {folder + "/" + MODULE_NAME, folder + "/" ODELAB_MODULE_FROM_BINARY "/" + MODULE_NAME}) {
    // RTLD_NOW: a symbol the module cannot find is reported here, not in
    // the middle of a frame.
    if (void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)) {
      using Entry = const WindowModule* (*)();
      if (const auto entry = reinterpret_cast<Entry>(dlsym(module, "odelab_window_module"))) return entry();
      why = dlerror();
      tried = path;
      break;
    }
    const char* error = dlerror();
    tried += (tried.empty() ? "" : ", ") + path;
    why += (why.empty() ? "" : "; ") + std::string(error ? error : "unknown error");
  }
  std::cerr << "error: the window module " << MODULE_NAME << " cannot be loaded (tried " << tried << "): " << why
            << "\n";
  return nullptr;
}

}  // namespace

const WindowModule* windowModule() {
  static const WindowModule* const entry = load();
  return entry;
}

}  // namespace odelab
