#include "ridefit/distributed/mpi_session.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <thread>

#ifdef RIDEFIT_HAVE_MPI
#include <mpi.h>
#endif

namespace ridefit::distributed {
namespace {

const MpiSession* the_session = nullptr;

// Open MPI, MPICH and PMIx-based launchers each set one of these in every process they start.
bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK"}) {
    if (std::getenv(name) != nullptr) return true;
  }
  return false;
}

}  // namespace

MpiSession::MpiSession([[maybe_unused]] int& argc, [[maybe_unused]] char**& argv) {
#ifdef RIDEFIT_HAVE_MPI
  if (launched_by_mpi()) {
    int provided = MPI_THREAD_SINGLE;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
    active_ = true;
    serialized_ = provided >= MPI_THREAD_SERIALIZED;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    MPI_Comm node;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    MPI_Comm_size(node, &ranks_on_node_);
    MPI_Comm_free(&node);
  }
#else
  if (launched_by_mpi()) {
    std::cerr << "ridefit: warning: started by mpirun, but this ridefit was built without MPI: "
                 "each process runs the whole command on its own\n";
  }
#endif
  the_session = this;
}

MpiSession::~MpiSession() {
  the_session = nullptr;
#ifdef RIDEFIT_HAVE_MPI
  if (active_) MPI_Finalize();
#endif
}

void MpiSession::abort(int exit_code) const {
#ifdef RIDEFIT_HAVE_MPI
  if (active_) MPI_Abort(MPI_COMM_WORLD, exit_code);
#endif
  std::exit(exit_code);
}

const MpiSession* MpiSession::current() { return the_session; }

bool MpiSession::built_with_mpi() {
#ifdef RIDEFIT_HAVE_MPI
  return true;
#else
  return false;
#endif
}

std::string broadcast_from_root([[maybe_unused]] const MpiSession& session, std::string bytes) {
#ifdef RIDEFIT_HAVE_MPI
  if (!session.active() || session.size() == 1) return bytes;
  std::uint64_t size = bytes.size();
  MPI_Bcast(&size, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  if (size > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
    throw std::runtime_error("broadcast_from_root: more than 2 GiB");
  }
  bytes.resize(size);
  MPI_Bcast(bytes.data(), static_cast<int>(size), MPI_BYTE, 0, MPI_COMM_WORLD);
#endif
  return bytes;
}

unsigned default_threads_per_rank(const MpiSession& session) {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  return std::max(1u, cores / static_cast<unsigned>(std::max(1, session.ranks_on_this_node())));
}

}  // namespace ridefit::distributed
