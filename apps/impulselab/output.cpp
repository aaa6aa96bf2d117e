// SPDX-License-Identifier: GPL-3.0-or-later
#include "output.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string_view>
#include <vector>

#include "app.hpp"
#include "impulse/core/error.hpp"

namespace impulselab {

namespace {

bool is_stdout(const std::string& path) {
  return path.empty() || path == "-";
}

std::string system_error(std::string_view what, const std::string& path, int error) {
  std::string message(what);
  message.append(" ").append(path).append(": ").append(std::strerror(error));
  return message;
}

// The whole of a stream, up to one byte past max_bytes (a pipe or a device has no size to ask
// first): the caller refuses what is longer. A failure is "<cannot> <the system's reason>".
std::string read_all(std::FILE* stream, std::size_t max_bytes, const std::string& cannot) {
  std::string text;
  std::array<char, 65536> buffer{};
  std::size_t count = 0;
  const auto room = [&] {  // up to one byte past the limit (no overflow at its largest value)
    const std::size_t left = max_bytes - text.size();
    return left < buffer.size() ? left + 1 : buffer.size();
  };
  while (text.size() <= max_bytes && (count = std::fread(buffer.data(), 1, room(), stream)) > 0) {
    text.append(buffer.data(), count);
  }
  if (std::ferror(stream) != 0) {
    throw impulse::InvalidInput(cannot + " " + std::strerror(errno));
  }
  return text;
}

// The permissions the output file ends up with: those of the file it replaces, or those a
// plain new file would get.
mode_t output_mode(const std::string& path) {
  struct stat existing {};
  if (::stat(path.c_str(), &existing) == 0 && S_ISREG(existing.st_mode)) {
    return existing.st_mode & 07777;
  }
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return static_cast<mode_t>(0666) & ~mask;
}

}  // namespace

std::string scene_name(const std::string& path) {
  return path == "-" ? "<stdin>" : path;
}

std::string read_file(const std::string& path, std::size_t max_bytes) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw impulse::InvalidInput(path + ": cannot read: it is a directory");
  }
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                             &std::fclose);
  if (!file) {
    throw impulse::InvalidInput(path + ": cannot read: " + std::strerror(errno));
  }
  return read_all(file.get(), max_bytes, path + ": cannot read:");
}

std::string read_input(const std::string& path, std::size_t max_bytes) {
  return path == "-" ? read_all(stdin, max_bytes, "cannot read <stdin>:")
                     : read_file(path, max_bytes);
}

void print_warnings(const std::vector<std::string>& warnings) {
  for (const std::string& warning : warnings) {
    std::fprintf(stderr, "impulselab: warning: %s\n", warning.c_str());
  }
}

void write_output(const std::string& path, const std::function<void(std::FILE*)>& write) {
  if (is_stdout(path)) {
    write(stdout);
    if (std::fflush(stdout) != 0 || std::ferror(stdout) != 0) {
      throw UsageError(system_error("cannot write to", "standard output", errno));
    }
    return;
  }
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::error_code ignored;
  if (fs::is_directory(target, ignored)) {
    throw UsageError("cannot write " + path + ": it is a directory");
  }
  if (!target.has_filename()) {
    throw UsageError("cannot write " + path + ": not a file name");
  }
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string pattern = (folder / ("." + target.filename().string() + ".tmp-XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) {
    throw UsageError(system_error("cannot create a temporary file in", folder.string(), errno));
  }
  const std::string temporary(name.data());
  std::FILE* file = ::fdopen(fd, "wb");
  if (file == nullptr) {
    const int error = errno;
    ::close(fd);
    ::unlink(temporary.c_str());
    throw UsageError(system_error("cannot write", temporary, error));
  }
  // From here on, any failure removes the temporary file and leaves `path` as it was.
  const auto abandon = [&](int error) {
    std::fclose(file);
    ::unlink(temporary.c_str());
    throw UsageError(system_error("cannot write", path, error));
  };
  try {
    write(file);
  } catch (...) {
    std::fclose(file);
    ::unlink(temporary.c_str());
    throw;
  }
  if (std::fflush(file) != 0 || std::ferror(file) != 0) {
    abandon(errno != 0 ? errno : EIO);
  }
  if (::fchmod(fd, output_mode(path)) != 0 || ::fsync(fd) != 0) {
    abandon(errno);
  }
  if (std::fclose(file) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    throw UsageError(system_error("cannot write", path, error));
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    throw UsageError(system_error("cannot replace", path, error));
  }
}

bool colour_wanted(const std::string& path) {
  if (!is_stdout(path) || ::isatty(STDOUT_FILENO) == 0) {
    return false;
  }
  const char* term = std::getenv("TERM");
  return std::getenv("NO_COLOR") == nullptr &&
         !(term != nullptr && std::string_view(term) == "dumb");
}

}  // namespace impulselab
