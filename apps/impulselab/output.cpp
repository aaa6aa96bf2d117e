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
#include <string_view>
#include <vector>

#include "app.hpp"
#include "impulse/core/error.hpp"
#include "impulse/scene/json.hpp"

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

// At most one byte more than a scene may hold: parse_scene then refuses it as too large.
std::string read_stdin() {
  constexpr std::size_t max_bytes = impulse::scene::ReadLimits{}.max_bytes;
  std::string text;
  std::array<char, 65536> buffer{};
  std::size_t count = 0;
  while (text.size() <= max_bytes &&
         (count = std::fread(buffer.data(), 1, std::min(buffer.size(), max_bytes + 1 - text.size()),
                             stdin)) > 0) {
    text.append(buffer.data(), count);
  }
  if (std::ferror(stdin) != 0) {
    throw impulse::InvalidInput(system_error("cannot read", "<stdin>", errno));
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

impulse::scene::World read_world(const std::string& path) {
  if (path == "-") {
    return impulse::scene::parse_world(read_stdin(), scene_name(path));
  }
  return impulse::scene::load_world(path);
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
