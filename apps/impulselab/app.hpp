// SPDX-License-Identifier: GPL-3.0-or-later
// The frame every verb runs in: the command line, the exit status, the error messages.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <stdexcept>
#include <string>

namespace impulselab {

/// Exit statuses of the command-line contract.
inline constexpr int exit_success = 0;  ///< the work was done
inline constexpr int exit_failure = 1;  ///< the work ran and found a failure (or a defect of ours)
inline constexpr int exit_usage = 2;    ///< bad usage or bad input; the message is on stderr

/// Bad usage found after the command line was parsed (a malformed range, an unwritable
/// --output): exit 2, the message on stderr.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Bad input at a place of a file, already in the form `FILE:LINE:COLUMN: what was expected`
/// (the way compilers and editors name a place): exit 2, printed as it is on stderr.
class PlacedError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The work ran and found a failure: exit 1, the message on stderr.
class WorkFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Runs the program: builds the command line with the verbs that @p add_verbs adds (each verb
/// does its work in its CLI11 callback and throws to fail), parses @p argv, and maps every
/// outcome to an exit status: 0 done (also --help and --version), 1 WorkFailed or an
/// unexpected exception, 2 a command-line error, impulse::InvalidInput, UsageError or
/// PlacedError. Never
/// lets an exception escape; SIGPIPE and SIGXFSZ are ignored so that a failed write is an
/// error message, not a signal.
int run(int argc, char** argv, const std::function<void(CLI::App&)>& add_verbs);

}  // namespace impulselab
