#pragma once

#include <string>

namespace ridefit::distributed {

// The process's place in an MPI run (`mpirun -np N ridefit …`). MPI is started only when the
// process was launched by an MPI launcher (its environment names a rank), so a plain `ridefit`
// never pays for it; otherwise, and in a build without MPI, the session is rank 0 of 1.
// One per process, made first in main() and ended last.
class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool root() const { return rank_ == 0; }
  // True when the session runs over MPI (launched by mpirun in a build with MPI).
  bool active() const { return active_; }
  // The number of this run's ranks on this machine (1 without MPI): each rank's share of the
  // cores is the cores over this.
  int ranks_on_this_node() const { return ranks_on_node_; }
  // True when a second thread may make MPI calls while the main thread computes (rank 0's
  // scheduler thread; MPI_THREAD_SERIALIZED or better).
  bool threads_may_call_mpi() const { return serialized_; }

  // Ends the whole run from any rank (MPI_Abort; std::exit without MPI): for a failure other
  // ranks cannot learn of, so that none waits for ever.
  [[noreturn]] void abort(int exit_code) const;

  // The session of this process; nullptr before one was made.
  static const MpiSession* current();

  // True when the build has MPI (RIDEFIT_WITH_MPI and Open MPI found).
  static bool built_with_mpi();

 private:
  int rank_ = 0;
  int size_ = 1;
  int ranks_on_node_ = 1;
  bool active_ = false;
  bool serialized_ = false;
};

// Rank 0's `bytes` on every rank (a collective call: every rank of the session makes it; the
// other ranks' `bytes` are ignored). Without MPI, `bytes` unchanged.
std::string broadcast_from_root(const MpiSession& session, std::string bytes);

// The threads each rank uses by default: every core of the machine shared among this
// machine's ranks (at least 1).
unsigned default_threads_per_rank(const MpiSession& session);

}  // namespace ridefit::distributed
