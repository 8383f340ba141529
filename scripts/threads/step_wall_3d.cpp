// Steps the settled S3D wall (bricks, steps from the command line) and prints the time stamp
// counter before and after the timed steps, for gomp_run_trace.c and run_balance.py. Build with
// the project's core library, -no-pie so that run_balance.py can name the loops:
//   g++ -std=c++20 -O2 -fopenmp -no-pie -Isrc -I. scripts/threads/step_wall_3d.cpp build/libblockdem_core.a \
//       -o step_wall_3d (and the core's libraries: fmt, toml++, hdf5, dxflib, glpk, MPI)
#include <cstdio>
#include <cstdlib>
#include <x86intrin.h>
#include "scenes/s3d_wall_3d.hpp"
#include "world/step_3d.hpp"
int main(int argc, char** argv) {
    blockdem::scenes::S3dWallDef def;
    def.bricks = argc > 1 ? std::atoi(argv[1]) : 1000;
    const int steps = argc > 2 ? std::atoi(argv[2]) : 20;
    blockdem::World3d w = blockdem::scenes::settled_s3d_wall_3d(def);
    for (int i = 0; i < 3; ++i) blockdem::step_3d(w);
    std::printf("start %llu\n", __rdtsc());
    for (int i = 0; i < steps; ++i) blockdem::step_3d(w);
    std::printf("end %llu\n", __rdtsc());
}
