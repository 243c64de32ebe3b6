#include "StreamedFile.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "SafeFile.h"

namespace odelab {

namespace {

// The holds in force and the files opened under them. A compare run's
// scenes are built on the main thread, but their files are closed on the
// threads that ran them: the list is guarded.
std::mutex heldMutex;
int holdDepth = 0;
std::vector<StreamedFile*> heldFiles;

}  // namespace

StreamedFile::Hold::Hold() {
  const std::lock_guard<std::mutex> lock(heldMutex);
  ++holdDepth;
}

StreamedFile::Hold::~Hold() {
  if (released_) return;
  // Ended without a release: a refusal or a failure while the run was being
  // set up. The files held are dropped without touching their paths.
  const std::lock_guard<std::mutex> lock(heldMutex);
  --holdDepth;
  for (StreamedFile* file : heldFiles) {
    file->held_ = false;
    file->kept_.clear();
  }
  heldFiles.clear();
}

void StreamedFile::Hold::release() {
  if (released_) return;
  released_ = true;
  std::vector<StreamedFile*> files;
  {
    const std::lock_guard<std::mutex> lock(heldMutex);
    if (--holdDepth > 0) return;  // an outer hold decides
    files.swap(heldFiles);
  }
  for (StreamedFile* file : files) file->held_ = false;
  for (StreamedFile* file : files) file->openNow();
}

StreamedFile::~StreamedFile() {
  forget();
  if (file_) std::fclose(file_);
}

void StreamedFile::forget() {
  if (!held_) return;
  const std::lock_guard<std::mutex> lock(heldMutex);
  heldFiles.erase(std::remove(heldFiles.begin(), heldFiles.end(), this), heldFiles.end());
  held_ = false;
  kept_.clear();
}

void StreamedFile::open(const std::string& path) {
  close();
  path_ = path;
  {
    const std::lock_guard<std::mutex> lock(heldMutex);
    if (holdDepth > 0) {
      held_ = true;
      kept_.clear();
      heldFiles.push_back(this);
      return;
    }
  }
  file_ = openExclusiveOutput(path);
}

void StreamedFile::openNow() {
  std::string text;
  text.swap(kept_);
  file_ = openExclusiveOutput(path_);
  write(text);
}

void StreamedFile::write(const std::string& text) {
  if (held_) {
    kept_ += text;
    return;
  }
  if (!file_) return;
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size() || std::fflush(file_) != 0) fail();
}

void StreamedFile::close() {
  forget();
  std::FILE* file = file_;
  file_ = nullptr;
  if (file && std::fclose(file) != 0 && !std::uncaught_exceptions()) fail();
}

void StreamedFile::fail() { throw std::runtime_error("cannot write '" + path_ + "': " + std::strerror(errno)); }

}  // namespace odelab
