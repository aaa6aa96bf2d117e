// SPDX-License-Identifier: GPL-3.0-or-later
// Running the built impulselab program from the tests: arguments in, exit status, standard
// output and standard error out, in a scratch folder of its own per test process.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace impulselab::test {

namespace fs = std::filesystem;

/// A scratch folder for this test process, removed when the process ends.
inline const fs::path& scratch() {
  struct Folder {
    fs::path path;
    Folder() {
      std::string pattern = (fs::temp_directory_path() / "impulselab-cli-XXXXXX").string();
      if (::mkdtemp(pattern.data()) == nullptr) {
        throw std::runtime_error("mkdtemp failed");
      }
      path = pattern;
    }
    ~Folder() {
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
  };
  static const Folder folder;
  return folder.path;
}

/// A fresh empty folder inside the scratch folder.
inline fs::path fresh_folder(const std::string& name) {
  const fs::path path = scratch() / name;
  fs::remove_all(path);
  fs::create_directories(path);
  return path;
}

/// 'text' for the shell.
inline std::string quote(const std::string& text) {
  std::string quoted("'");
  for (const char c : text) {
    quoted.append(c == '\'' ? "'\\''" : std::string(1, c));
  }
  return quoted.append("'");
}

inline std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

inline std::string scene_path(const std::string& name) {
  return std::string(IMPULSELAB_SCENES_DIR) + "/" + name;
}

inline std::string cli_tests_path(const std::string& name) {
  return std::string(IMPULSELAB_CLI_TESTS_DIR) + "/" + name;
}

/// The worked example of section 1 as a scene file (tests/cli/scenes/): what many tests solve.
inline const std::string worked = cli_tests_path("scenes/worked-example.json");

/// What a run of the program gave.
struct Run {
  int status = -1;         ///< exit status (when it exited)
  bool signalled = false;  ///< it ended on a signal
  std::string out;         ///< standard output
  std::string err;         ///< standard error
};

/// Runs `<program> <arguments>` (already quoted for the shell) with standard input from
/// @p input (or /dev/null). @p shell_prefix runs before it in the same shell (e.g. "ulimit -f 8;
/// cd DIR;").
inline Run run_program(const std::string& program, const std::string& arguments,
                       const std::string& input = "/dev/null",
                       const std::string& shell_prefix = "") {
  static int counter = 0;
  ++counter;
  const fs::path out = scratch() / ("out-" + std::to_string(counter));
  const fs::path err = scratch() / ("err-" + std::to_string(counter));
  const std::string command = shell_prefix + " exec " + quote(program) + " " + arguments + " < " +
                              quote(input) + " > " + quote(out.string()) + " 2> " +
                              quote(err.string());
  const int raw = std::system(command.c_str());
  Run r;
  if (WIFEXITED(raw)) {
    r.status = WEXITSTATUS(raw);
  }
  r.signalled = WIFSIGNALED(raw);
  r.out = read_text(out);
  r.err = read_text(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

/// run_program() of the impulselab program.
inline Run run(const std::string& arguments, const std::string& input = "/dev/null",
               const std::string& shell_prefix = "") {
  return run_program(IMPULSELAB_BINARY, arguments, input, shell_prefix);
}

/// The lines of a text, without their newlines.
inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    result.push_back(line);
  }
  return result;
}

/// The comma-separated fields of a CSV line (no quoting: impulselab writes none).
inline std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> result;
  std::istringstream in(line);
  for (std::string field; std::getline(in, field, ',');) {
    result.push_back(field);
  }
  return result;
}

/// Whether a line of `text` holds `tokens` in this order (a row of a table, whatever its spacing).
inline bool has_row(const std::string& text, const std::vector<std::string>& tokens) {
  for (const std::string& line : lines(text)) {
    std::size_t at = 0;
    bool all = true;
    for (const std::string& token : tokens) {
      at = line.find(token, at);
      if (at == std::string::npos) {
        all = false;
        break;
      }
      at += token.size();
    }
    if (all) {
      return true;
    }
  }
  return false;
}

}  // namespace impulselab::test
