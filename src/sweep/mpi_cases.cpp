#include "sweep/mpi_cases.hpp"
#include "sweep/results_table.hpp"

#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#ifdef BLOCKDEM_WITH_MPI
#define OMPI_SKIP_MPICXX 1  // the C API only: no deprecated C++ bindings
#include <mpi.h>
#endif

namespace blockdem::sweep {

bool started_by_mpi_launcher() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"})
        if (std::getenv(name)) return true;
    return false;
}

#ifdef BLOCKDEM_WITH_MPI

namespace {

constexpr int tag_request = 1;  // worker -> rank 0: the previous case's row ("" at first)
constexpr int tag_assign = 2;   // rank 0 -> worker: a case id, or -1 to stop

// One request from any worker, if there is one: its source and the row it carries.
bool poll_request(int& source, std::string& row) {
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, tag_request, MPI_COMM_WORLD, &flag, &status);
    if (!flag) return false;
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    row.assign(static_cast<std::size_t>(length), '\0');
    source = status.MPI_SOURCE;
    MPI_Recv(row.data(), length, MPI_CHAR, source, tag_request, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return true;
}

}  // namespace

bool mpi_built() { return true; }

MpiSession::MpiSession() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided);
    serialized_ = provided >= MPI_THREAD_SERIALIZED;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() { MPI_Finalize(); }

bool MpiSession::all_true(bool mine) const {
    int in = mine ? 1 : 0, out = 0;
    MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    return out == 1;
}

std::int64_t MpiSession::sum(std::int64_t mine) const {
    std::int64_t out = 0;
    MPI_Allreduce(&mine, &out, 1, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
    return out;
}

void serve_remote_workers(CaseQueue& queue, ResultCollector& collector, std::int64_t remote_workers) {
    std::int64_t stopped = 0;
    int source = 0;
    std::string row;
    while (stopped < remote_workers) {
        if (!poll_request(source, row)) {
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
            continue;
        }
        if (!row.empty()) collector.record(leading_id(row), row);
        const std::optional<std::int64_t> id = queue.next();
        const std::int64_t reply = id ? *id : -1;
        if (!id) ++stopped;
        MPI_Send(&reply, 1, MPI_INT64_T, source, tag_assign, MPI_COMM_WORLD);
    }
}

void work_for_rank0(int threads, const std::function<std::string(std::int64_t)>& run_row) {
    std::mutex mpi_mutex;  // one request/reply exchange at a time per rank (MPI_THREAD_SERIALIZED)
    auto worker = [&] {
        std::string row;
        while (true) {
            std::int64_t id = -1;
            {
                std::lock_guard lock(mpi_mutex);
                MPI_Send(row.data(), static_cast<int>(row.size()), MPI_CHAR, 0, tag_request, MPI_COMM_WORLD);
                MPI_Recv(&id, 1, MPI_INT64_T, 0, tag_assign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            }
            if (id < 0) return;
            row = run_row(id);
        }
    };
    std::vector<std::thread> pool;
    for (int k = 1; k < threads; ++k) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
}

#else

bool mpi_built() { return false; }

MpiSession::MpiSession() {
    throw std::runtime_error("this blockdem was built without MPI (install libopenmpi-dev and rebuild)");
}
MpiSession::~MpiSession() = default;
bool MpiSession::all_true(bool mine) const { return mine; }
std::int64_t MpiSession::sum(std::int64_t mine) const { return mine; }
void serve_remote_workers(CaseQueue&, ResultCollector&, std::int64_t) {}
void work_for_rank0(int, const std::function<std::string(std::int64_t)>&) {}

#endif

}  // namespace blockdem::sweep
