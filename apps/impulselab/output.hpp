// SPDX-License-Identifier: GPL-3.0-or-later
// Input and output of the verbs: files or standard input in, results to standard output or,
// atomically, to a file. (Scenes are read in scene_input.hpp.)
#pragma once

#include <cstddef>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace impulselab {

/// The contents of a file up to one byte past @p max_bytes (a device or a pipe without end is
/// read no further): the caller refuses a text longer than @p max_bytes with its own words.
/// impulse::InvalidInput (`"<path>: cannot read: <reason>"`) when it cannot be read.
/// @param path the file
/// @param max_bytes the most the caller accepts
/// @return its bytes, at most @p max_bytes + 1
std::string read_file(const std::string& path, std::size_t max_bytes);

/// read_file(), or standard input when @p path is "-".
/// @param path a file or "-"
/// @param max_bytes the most the caller accepts
/// @return its bytes, at most @p max_bytes + 1
std::string read_input(const std::string& path, std::size_t max_bytes);

/// How messages name the scene at @p path: the path itself, or "<stdin>" for "-".
/// @param path a file or "-"
/// @return the name
std::string scene_name(const std::string& path);

/// Writes what @p write produces to @p path, or to standard output when @p path is empty or "-".
///
/// A file is written atomically: @p write fills a temporary file in the same folder, which is
/// flushed to disk and renamed over @p path only when all went well; on any failure (an
/// exception from @p write, a failed write, a full disk, a folder that does not exist) the
/// temporary file is removed, an existing @p path is left untouched and UsageError is thrown
/// (WorkFailed and InvalidInput thrown by @p write pass through unchanged). A new file gets the
/// permissions 0666 less the umask; a replaced file keeps its own.
/// @param path the file, "-" or empty
/// @param write writes the whole output to the stream it is given
void write_output(const std::string& path, const std::function<void(std::FILE*)>& write);

/// Prints each warning on standard error as `impulselab: warning: <warning>`. Warnings do not
/// change the exit status.
/// @param warnings the lines
void print_warnings(const std::vector<std::string>& warnings);

/// Whether output to standard output may use colour: it is a terminal, NO_COLOR is not set and
/// TERM is not "dumb".
/// @param path the --output value ("" or "-" is standard output)
/// @return true when colour is wanted
bool colour_wanted(const std::string& path);

}  // namespace impulselab
