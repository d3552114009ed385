// The `ridefit` command: one program with subcommands. Exit codes: 0 success, 1 a run that
// failed (solver failure, non-convergence), 2 bad input (files, keys, flags).
#include <fmt/core.h>
#include <glog/logging.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <thread>

#include "collective_run_error.h"
#include "ridefit/common/errors.h"
#include "ridefit/distributed/mpi_session.h"
#include "ridefit/io/temporary_files.h"
#include "ridefit/version.h"
#include "subcommands.h"

namespace {

// The end of a run that failed with `message`. One process prints it. Under mpirun every rank
// meets the same bad input, so rank 0 alone prints and then ends every rank (MPI_Abort), since
// a rank waiting for work from it would otherwise wait for ever; another rank keeps quiet and
// waits to be ended, and speaks and ends the run itself only when rank 0 has not failed (a
// failure of its own).
int fail(const ridefit::distributed::MpiSession& session, const std::string& message, int code) {
  if (!session.active() || session.size() == 1) {
    std::cerr << message << "\n";
    return code;
  }
  if (!session.root()) {
    std::this_thread::sleep_for(std::chrono::seconds(5));
    std::cerr << "rank " << session.rank() << ": " << message << "\n";
  } else {
    std::cerr << message << "\n";
  }
  std::cerr.flush();
  session.abort(code);
}

}  // namespace

int main(int argc, char** argv) {
  // Under mpirun: this process's rank (MPI ends when main returns).
  const ridefit::distributed::MpiSession session(argc, argv);
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
    const int code = session.root() ? app.exit(e) : (e.get_exit_code() == 0 ? 0 : 2);
    return code == 0 ? 0 : 2;
  } catch (const ridefit::InputError& e) {
    return fail(session, std::string("ridefit: error: ") + e.what(), 2);
  } catch (const ridefit::cli::CollectiveRunError& e) {
    if (session.root()) std::cerr << "ridefit: run failed: " << e.what() << "\n";
    return 1;
  } catch (const ridefit::RunError& e) {
    return fail(session, std::string("ridefit: run failed: ") + e.what(), 1);
  } catch (const std::bad_alloc&) {
    return fail(session, "ridefit: run failed: out of memory (lower the output rate or duration)",
                1);
  } catch (const std::exception& e) {
    return fail(session, std::string("ridefit: internal error: ") + e.what(), 1);
  }
  return 0;
}
