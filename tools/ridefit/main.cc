// The `ridefit` command: one program with subcommands. Exit codes: 0 success, 1 a run that
// failed (solver failure, non-convergence), 2 bad input (files, keys, flags).
#include <fmt/core.h>
#include <glog/logging.h>
#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <new>

#include "ridefit/common/errors.h"
#include "ridefit/io/temporary_files.h"
#include "ridefit/version.h"
#include "subcommands.h"

int main(int argc, char** argv) {
  // Ceres logs through glog; every condition it reports (a rank-deficient covariance, a
  // failed step) reaches the user in ridefit's own words, so its log stays quiet.
  FLAGS_minloglevel = google::GLOG_FATAL;
  google::InitGoogleLogging(argv[0]);
  // An interrupted run removes its temporary files and ends gnuplot before it dies.
  ridefit::io::install_temporary_cleanup();
  CLI::App app{"ridefit: vehicle vertical dynamics with suspension friction"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "ridefit " RIDEFIT_VERSION);
  ridefit::cli::register_subcommands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const ridefit::InputError& e) {
    std::cerr << "ridefit: error: " << e.what() << "\n";
    return 2;
  } catch (const ridefit::RunError& e) {
    std::cerr << "ridefit: run failed: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "ridefit: run failed: out of memory (lower the output rate or duration)\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "ridefit: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
