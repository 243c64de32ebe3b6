#include "Platform.h"

#include <fcntl.h>
#include <io.h>
#include <windows.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <csignal>
#include <stdexcept>

namespace odelab::platform {

const char* const FOLDER_SEPARATORS = "/\\";

namespace {

std::wstring wide(const std::string& text) {
  if (text.empty()) return {};
  const int length = MultiByteToWideChar(CP_ACP, 0, text.data(), static_cast<int>(text.size()), nullptr, 0);
  std::wstring out(static_cast<std::size_t>(length), L'\0');
  MultiByteToWideChar(CP_ACP, 0, text.data(), static_cast<int>(text.size()), out.data(), length);
  return out;
}

std::string narrow(const std::wstring& text) {
  if (text.empty()) return {};
  const int length =
      WideCharToMultiByte(CP_ACP, 0, text.data(), static_cast<int>(text.size()), nullptr, 0, nullptr, nullptr);
  std::string out(static_cast<std::size_t>(length), '\0');
  WideCharToMultiByte(CP_ACP, 0, text.data(), static_cast<int>(text.size()), out.data(), length, nullptr, nullptr);
  return out;
}

// A path handed back: "\\?\" dropped, '/' between folders, as on POSIX.
std::string portable(std::wstring path) {
  if (path.rfind(L"\\\\?\\UNC\\", 0) == 0)
    path = L"\\\\" + path.substr(8);
  else if (path.rfind(L"\\\\?\\", 0) == 0)
    path = path.substr(4);
  std::string out = narrow(path);
  std::replace(out.begin(), out.end(), '\\', '/');
  return out;
}

std::string message(DWORD error) {
  wchar_t* text = nullptr;
  const DWORD length = FormatMessageW(
      FORMAT_MESSAGE_ALLOCATE_BUFFER | FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS, nullptr, error, 0,
      reinterpret_cast<wchar_t*>(&text), 0, nullptr);
  std::string out = length ? narrow(std::wstring(text, length)) : "Windows error " + std::to_string(error);
  LocalFree(text);
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r' || out.back() == '.')) out.pop_back();
  return out;
}

// The kind of what an open handle names: devices (NUL, CON) and pipes are
// not files on disk; a reparse point is a link or a junction.
FileKind kindOfHandle(HANDLE handle) {
  const DWORD type = GetFileType(handle);
  if (type == FILE_TYPE_CHAR) return FileKind::Device;
  if (type == FILE_TYPE_PIPE) return FileKind::Fifo;
  if (type != FILE_TYPE_DISK) return FileKind::Other;
  BY_HANDLE_FILE_INFORMATION info{};
  if (!GetFileInformationByHandle(handle, &info)) return FileKind::Other;
  if (info.dwFileAttributes & FILE_ATTRIBUTE_REPARSE_POINT) return FileKind::Link;
  if (info.dwFileAttributes & FILE_ATTRIBUTE_DIRECTORY) return FileKind::Folder;
  return FileKind::Regular;
}

// Opens what `path` names itself (a link, not its target; a folder too),
// with no access to its contents, or INVALID_HANDLE_VALUE.
HANDLE openForInspection(const std::string& path) {
  return CreateFileW(wide(path).c_str(), FILE_READ_ATTRIBUTES, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE,
                     nullptr, OPEN_EXISTING, FILE_FLAG_BACKUP_SEMANTICS | FILE_FLAG_OPEN_REPARSE_POINT, nullptr);
}

// CON, PRN, AUX, NUL, COM1-9 and LPT1-9, with any extension, name devices in
// every folder; opening one may fail (CON without a console) yet it is no file.
bool isReservedDeviceName(const std::string& path) {
  const auto slash = path.find_last_of(FOLDER_SEPARATORS);
  std::string name = path.substr(slash == std::string::npos ? 0 : slash + 1);
  name = name.substr(0, name.find('.'));
  while (!name.empty() && name.back() == ' ') name.pop_back();
  for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (name == "CON" || name == "PRN" || name == "AUX" || name == "NUL") return true;
  return name.size() == 4 && (name.rfind("COM", 0) == 0 || name.rfind("LPT", 0) == 0) && name[3] >= '1' &&
         name[3] <= '9';
}

std::atomic<unsigned> uniqueCounter{0};

}  // namespace

FileKind fileKind(const std::string& path) {
  if (isReservedDeviceName(path)) return FileKind::Device;
  const HANDLE handle = openForInspection(path);
  if (handle == INVALID_HANDLE_VALUE) {
    const DWORD error = GetLastError();
    if (error == ERROR_FILE_NOT_FOUND || error == ERROR_PATH_NOT_FOUND) return FileKind::Absent;
    // Held open without sharing (a pipe's other end, a locked file) yet
    // present: only its attributes can be read.
    const DWORD attributes = GetFileAttributesW(wide(path).c_str());
    if (attributes == INVALID_FILE_ATTRIBUTES) return FileKind::Absent;
    if (attributes & FILE_ATTRIBUTE_REPARSE_POINT) return FileKind::Link;
    if (attributes & FILE_ATTRIBUTE_DIRECTORY) return FileKind::Folder;
    return FileKind::Regular;
  }
  const FileKind kind = kindOfHandle(handle);
  CloseHandle(handle);
  return kind;
}

bool sameName(const std::string& a, const std::string& b) {
  const std::wstring wa = wide(a), wb = wide(b);
  return CompareStringOrdinal(wa.data(), static_cast<int>(wa.size()), wb.data(), static_cast<int>(wb.size()), TRUE) ==
         CSTR_EQUAL;
}

std::string canonicalPath(const std::string& path) {
  // Opened (following links) so the answer is the file's final path.
  const HANDLE handle = CreateFileW(wide(path).c_str(), FILE_READ_ATTRIBUTES,
                                    FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, nullptr, OPEN_EXISTING,
                                    FILE_FLAG_BACKUP_SEMANTICS, nullptr);
  if (handle == INVALID_HANDLE_VALUE) return "";
  std::wstring buffer(32768, L'\0');
  const DWORD length = GetFinalPathNameByHandleW(handle, buffer.data(), static_cast<DWORD>(buffer.size()), 0);
  CloseHandle(handle);
  if (length == 0 || length >= buffer.size()) return "";
  buffer.resize(length);
  return portable(buffer);
}

std::string executablePath() {
  std::wstring buffer(32768, L'\0');
  const DWORD length = GetModuleFileNameW(nullptr, buffer.data(), static_cast<DWORD>(buffer.size()));
  if (length == 0 || length >= buffer.size()) return "";
  buffer.resize(length);
  return portable(buffer);
}

std::string writeNewFile(const std::string& stem, const std::string& bytes) {
  // CREATE_NEW fails on any existing name, a link included: the file opened
  // is always the one just made. The suffix: process, time and a counter.
  HANDLE handle = INVALID_HANDLE_VALUE;
  std::string path;
  for (int attempt = 0; attempt < 100 && handle == INVALID_HANDLE_VALUE; ++attempt) {
    path = stem + std::to_string(GetCurrentProcessId()) + "-" + std::to_string(GetTickCount64()) + "-" +
           std::to_string(uniqueCounter++);
    handle = CreateFileW(wide(path).c_str(), GENERIC_WRITE, 0, nullptr, CREATE_NEW, FILE_ATTRIBUTE_NORMAL, nullptr);
    if (handle == INVALID_HANDLE_VALUE && GetLastError() != ERROR_FILE_EXISTS)
      throw std::runtime_error("cannot create a temporary file: " + message(GetLastError()));
  }
  if (handle == INVALID_HANDLE_VALUE) throw std::runtime_error("cannot create a temporary file: no free name");
  auto fail = [&](const std::string& reason) {
    DeleteFileW(wide(path).c_str());
    return std::runtime_error(reason);
  };
  std::size_t written = 0;
  while (written < bytes.size()) {
    const DWORD chunk = static_cast<DWORD>(std::min<std::size_t>(bytes.size() - written, 1u << 30));
    DWORD n = 0;
    if (!WriteFile(handle, bytes.data() + written, chunk, &n, nullptr) || n == 0) {
      const std::string reason = n == 0 ? "nothing written" : message(GetLastError());
      CloseHandle(handle);
      throw fail(reason);
    }
    written += n;
  }
  if (!CloseHandle(handle)) throw fail(message(GetLastError()));
  return path;
}

std::string replaceFile(const std::string& source, const std::string& target) {
  if (MoveFileExW(wide(source).c_str(), wide(target).c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH))
    return "";
  return message(GetLastError());
}

void removeFile(const std::string& path) { DeleteFileW(wide(path).c_str()); }

OutputFile openHeldOutput(const std::string& path) {
  const auto refuse = OutputFile::refused;
  OutputFile out;
  // The link itself is opened, never its target, and looked at before a
  // byte is written. Sharing reading only: a second writer's open fails
  // with a sharing violation, and readers still see the rows.
  const HANDLE handle = CreateFileW(wide(path).c_str(), GENERIC_WRITE, FILE_SHARE_READ, nullptr, OPEN_ALWAYS,
                                    FILE_ATTRIBUTE_NORMAL | FILE_FLAG_OPEN_REPARSE_POINT, nullptr);
  if (handle == INVALID_HANDLE_VALUE) {
    const DWORD error = GetLastError();
    if (error == ERROR_SHARING_VIOLATION || error == ERROR_LOCK_VIOLATION)
      return refuse(OutputFile::Refusal::Held, "held by another process");
    const FileKind kind = fileKind(path);
    if (kind != FileKind::Regular && kind != FileKind::Absent)
      return refuse(kind == FileKind::Link ? OutputFile::Refusal::Link : OutputFile::Refusal::NotRegular,
                    describe(kind));
    return refuse(OutputFile::Refusal::Failed, message(error));
  }
  const FileKind kind = kindOfHandle(handle);
  if (kind != FileKind::Regular) {
    CloseHandle(handle);
    return refuse(kind == FileKind::Link ? OutputFile::Refusal::Link : OutputFile::Refusal::NotRegular,
                  describe(kind));
  }
  BY_HANDLE_FILE_INFORMATION info{};
  if (GetFileInformationByHandle(handle, &info) && info.nNumberOfLinks > 1) {
    CloseHandle(handle);
    return refuse(OutputFile::Refusal::Shared, "has more than one link (a hard link: another name shares its contents)");
  }
  if (!SetEndOfFile(handle)) {
    const DWORD error = GetLastError();
    CloseHandle(handle);
    return refuse(OutputFile::Refusal::Failed, message(error));
  }
  const int fd = _open_osfhandle(reinterpret_cast<intptr_t>(handle), _O_WRONLY | _O_BINARY);
  if (fd < 0) {
    CloseHandle(handle);
    return refuse(OutputFile::Refusal::Failed, "cannot make a stream of it");
  }
  out.file = _fdopen(fd, "wb");
  if (!out.file) {
    _close(fd);
    return refuse(OutputFile::Refusal::Failed, "cannot make a stream of it");
  }
  return out;
}

TargetFacts targetFacts(const std::string& path, const std::string&) {
  TargetFacts facts;
  facts.kind = fileKind(path);
  if (facts.kind == FileKind::Absent) return facts;
  // Windows has no sticky folders; its hard links count as on POSIX.
  const HANDLE handle = openForInspection(path);
  BY_HANDLE_FILE_INFORMATION info{};
  facts.links = 1;
  if (handle != INVALID_HANDLE_VALUE) {
    if (GetFileInformationByHandle(handle, &info)) facts.links = info.nNumberOfLinks;
    CloseHandle(handle);
  }
  return facts;
}

std::string probeNewFile(const std::string& stem) {
  try {
    removeFile(writeNewFile(stem, ""));
  } catch (const std::exception& error) {
    const std::string why = error.what();
    if (why.find(message(ERROR_FILENAME_EXCED_RANGE)) != std::string::npos)
      return "name is too long: the hidden temporary file beside it cannot be named";
    return "cannot create a file there: " + why.substr(why.find(": ") + 2);
  }
  return "";
}

std::string readRegularFile(const std::string& path, std::size_t maxBytes, std::string& bytes) {
  if (isReservedDeviceName(path)) return describe(FileKind::Device);
  const HANDLE handle = CreateFileW(wide(path).c_str(), GENERIC_READ, FILE_SHARE_READ | FILE_SHARE_WRITE, nullptr,
                                    OPEN_EXISTING, FILE_FLAG_BACKUP_SEMANTICS, nullptr);
  if (handle == INVALID_HANDLE_VALUE) {
    const DWORD error = GetLastError();
    return error == ERROR_FILE_NOT_FOUND || error == ERROR_PATH_NOT_FOUND ? "does not exist" : message(error);
  }
  std::string why;
  LARGE_INTEGER size{};
  const FileKind kind = kindOfHandle(handle);
  if (kind != FileKind::Regular)
    why = describe(kind);
  else if (!GetFileSizeEx(handle, &size))
    why = message(GetLastError());
  else if (static_cast<unsigned long long>(size.QuadPart) > maxBytes)
    why = "is larger than " + std::to_string(maxBytes) + " bytes";
  if (why.empty()) {
    bytes.resize(static_cast<std::size_t>(size.QuadPart));
    std::size_t got = 0;
    while (got < bytes.size()) {
      DWORD n = 0;
      const DWORD chunk = static_cast<DWORD>(std::min<std::size_t>(bytes.size() - got, 1u << 30));
      if (!ReadFile(handle, &bytes[got], chunk, &n, nullptr) || n == 0) break;
      got += n;
    }
    if (got != bytes.size()) why = "could not be read whole";
  }
  CloseHandle(handle);
  return why;
}

void onStopRequest(void (*handler)(int)) {
  // The C library turns Ctrl+C and Ctrl+Break into SIGINT and SIGBREAK;
  // both are reported as SIGINT, a stop asked for at the keyboard.
  std::signal(SIGINT, handler);
  static void (*stop)(int) = nullptr;
  stop = handler;
  std::signal(SIGBREAK, [](int) { stop(SIGINT); });
}

}  // namespace odelab::platform
