// --threads N of `blockdem run` and `blockdem bench`: the OpenMP threads of the time step.
#ifdef _OPENMP
#include <omp.h>
#endif

#include "apps/blockdem/commands.hpp"

namespace blockdem::cli {

void set_step_threads(int n) {
    if (n < 1) throw CLI::ValidationError("--threads", "must be 1 or more");
#ifdef _OPENMP
    omp_set_num_threads(n);
#else
    if (n != 1) throw CLI::ValidationError("--threads", "this blockdem was built without OpenMP: only 1 thread");
#endif
}

}  // namespace blockdem::cli
