// SPDX-License-Identifier: GPL-3.0-or-later
#include "app.hpp"

#include <csignal>
#include <cstdio>
#include <exception>

#include "impulse/core/error.hpp"

namespace impulselab {

namespace {
int report(int status, const char* message) {
  std::fflush(stdout);
  std::fprintf(stderr, "impulselab: error: %s\n", message);
  return status;
}
}  // namespace

int run(int argc, char** argv, const std::function<void(CLI::App&)>& add_verbs) {
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    CLI::App app(
        "ImpulseLab: collision impulses in the form A·Fdt = B (the paper \"Collision "
        "handling\").",
        "impulselab");
    app.set_version_flag("--version", std::string("impulselab ") + IMPULSELAB_VERSION);
    app.require_subcommand(1);
    app.footer(
        "Exit status: 0 done; 1 the work ran and found a failure; 2 bad usage or bad input.");
    add_verbs(app);
    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      // --help and --version are "errors" with status 0; every real command-line error is 2.
      const int status = app.exit(e);
      return status == 0 ? exit_success : exit_usage;
    }
    return exit_success;
  } catch (const impulse::InvalidInput& e) {
    return report(exit_usage, e.what());
  } catch (const UsageError& e) {
    return report(exit_usage, e.what());
  } catch (const PlacedError& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s\n", e.what());
    return exit_usage;
  } catch (const WorkFailed& e) {
    return report(exit_failure, e.what());
  } catch (const std::exception& e) {
    std::string message("internal error (please report it): ");
    message.append(e.what());
    return report(exit_failure, message.c_str());
  } catch (...) {
    return report(exit_failure, "internal error (please report it): unknown exception");
  }
}

}  // namespace impulselab
