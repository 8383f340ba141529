#pragma once
// How Simulation.step and Simulation3d.step take n steps for Python: one stepping thread at a
// time (the GIL is released while it steps, so another Python thread could call in), in chunks
// between which Ctrl-C (KeyboardInterrupt) is seen. The run does not depend on how it is cut
// (world/simulation.hpp, RunLoop), so an interrupted run can go on.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <future>
#include <stdexcept>

#include <pybind11/pybind11.h>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace blockdem::python {

/// Steps between two looks at Python's signals (Ctrl-C).
inline constexpr std::int64_t steps_between_signal_checks = 256;

/// Holds `stepping` for the duration (std::logic_error if another thread holds it).
class SteppingGuard {
public:
    explicit SteppingGuard(std::atomic<bool>& stepping) : stepping_(stepping) {
        if (stepping_.exchange(true)) throw std::logic_error("the simulation is being stepped in another thread");
    }
    ~SteppingGuard() { stepping_ = false; }
    SteppingGuard(const SteppingGuard&) = delete;
    SteppingGuard& operator=(const SteppingGuard&) = delete;

private:
    std::atomic<bool>& stepping_;
};

/// Takes up to `steps` steps through step_chunk(k) (up to k steps, returning how many: fewer at the
/// end of the run), on `threads` OpenMP threads without the GIL; returns the steps taken.
template <class StepChunk>
std::int64_t step_in_chunks(std::int64_t steps, int threads, StepChunk&& step_chunk) {
    std::int64_t taken = 0;
    do {
        const std::int64_t chunk = std::min(steps - taken, steps_between_signal_checks);
        std::int64_t got = 0;
        {
            pybind11::gil_scoped_release release;
#ifdef _OPENMP
            omp_set_num_threads(threads);  // (per calling thread: the one that steps)
#else
            (void)threads;
#endif
            got = step_chunk(chunk);
        }
        taken += got;
        if (got < chunk) break;  // the end of the run
        if (PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
    } while (taken < steps);
    return taken;
}

/// Builds a run through build(&stop) (which may settle the model for minutes) on another thread,
/// without the GIL and on `threads` OpenMP threads, while this thread looks at Python's signals
/// every 0.1 s: Ctrl-C sets stop, which ends the settling at a whole step, and raises
/// KeyboardInterrupt here (nothing was built). Signals can only be seen on the thread that
/// called in, hence the second thread. `stop` must outlive what is built (a run keeps the
/// pointer for its own stop requests).
template <class Build>
auto build_watching_signals(int threads, std::atomic<bool>& stop, Build&& build) {
    auto built = std::async(std::launch::async, [&] {
#ifdef _OPENMP
        omp_set_num_threads(threads);  // (per thread: the one that builds)
#else
        (void)threads;
#endif
        return build(&stop);
    });
    for (;;) {
        bool ready = false;
        {
            pybind11::gil_scoped_release release;
            ready = built.wait_for(std::chrono::milliseconds(100)) == std::future_status::ready;
        }
        if (ready) return built.get();
        if (PyErr_CheckSignals() != 0) {
            stop = true;
            {
                pybind11::gil_scoped_release release;
                built.wait();
            }
            throw pybind11::error_already_set();  // (the build's own result or error is dropped)
        }
    }
}

}  // namespace blockdem::python
