#include "StreamedFile.h"

#include <cerrno>
#include <cstring>
#include <exception>
#include <stdexcept>

#include "SafeFile.h"

namespace odelab {

StreamedFile::~StreamedFile() {
  if (file_) std::fclose(file_);
}

void StreamedFile::open(const std::string& path) {
  close();
  path_ = path;
  file_ = openExclusiveOutput(path);
}

void StreamedFile::write(const std::string& text) {
  if (!file_) return;
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size() || std::fflush(file_) != 0) fail();
}

void StreamedFile::close() {
  std::FILE* file = file_;
  file_ = nullptr;
  if (file && std::fclose(file) != 0 && !std::uncaught_exceptions()) fail();
}

void StreamedFile::fail() { throw std::runtime_error("cannot write '" + path_ + "': " + std::strerror(errno)); }

}  // namespace odelab
