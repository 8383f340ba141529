#pragma once
// Sweeps over MPI ranks (`mpirun -n N blockdem sweep ...`), built when CMake finds MPI
// (BLOCKDEM_WITH_MPI). Rank 0 owns the queue and the results: its main thread hands out case
// ids one at a time to whichever remote worker asks next (dynamic load balancing: cases differ
// a lot in run time) and appends the rows they send back, while its other threads run cases
// too. The other ranks only compute. Without mpirun the binary never touches MPI.
#include <cstdint>
#include <functional>
#include <string>

#include "sweep/case_queue.hpp"

namespace blockdem::sweep {

/// True when this build has MPI.
bool mpi_built();

/// True when this process was started by mpirun/mpiexec/srun (their environment variables).
bool started_by_mpi_launcher();

/// MPI_Init_thread on construction, MPI_Finalize on destruction. Throws std::runtime_error in
/// a build without MPI.
class MpiSession {
public:
    MpiSession();
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }
    /// Whether several threads of a rank may call MPI (one at a time).
    bool threads_may_call() const { return serialized_; }
    /// True on every rank when `mine` is true on every rank (collective).
    bool all_true(bool mine) const;
    /// The sum of `mine` over all ranks (collective).
    std::int64_t sum(std::int64_t mine) const;

private:
    int rank_ = 0;
    int size_ = 1;
    bool serialized_ = false;
};

/// Rank 0, main thread: serves the remote workers (remote_workers of them over all other
/// ranks) until each has been told to stop, recording the rows they return. It polls with
/// short sleeps so that it leaves the core to rank 0's own workers.
void serve_remote_workers(CaseQueue& queue, ResultCollector& collector, std::int64_t remote_workers);

/// Ranks > 0: `threads` workers; each asks rank 0 for a case, runs run_row(id) (the formatted
/// row, or "" for a case cancelled by Ctrl-C) and sends it back with its next request.
void work_for_rank0(int threads, const std::function<std::string(std::int64_t)>& run_row);

}  // namespace blockdem::sweep
