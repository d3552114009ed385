#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "ridefit/distributed/mpi_session.h"
#include "ridefit/distributed/task_farm.h"
#include "ridefit/study/half_car_sweep.h"

namespace ridefit::cli {

// The study's runs over the ranks of `session` (each rank `threads` threads, 0 = its share of
// the cores), gathered on rank 0 bit for bit as one process computes them; the other ranks get
// an empty list. `progress` is called on rank 0, and `statistics` (may be null) filled there.
std::vector<study::SweepRow> run_distributed_sweep(
    const distributed::MpiSession& session, const study::HalfCarSweep& sweep, unsigned threads,
    const std::function<void(std::size_t, std::size_t)>& progress,
    distributed::TaskFarmStatistics* statistics = nullptr);

}  // namespace ridefit::cli
