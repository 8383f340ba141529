// What the host gives this VM's two vCPUs at the moment, as two numbers: how much two threads of
// pure register arithmetic get over one (about 2.0 when the vCPUs run on two physical cores,
// about 1.0 to 1.3 when they share one core's SMT threads or one is taken by another guest), and
// the same for a pass that streams through memory (below 2.0 when the host's memory bandwidth is
// shared). A wall-clock speed-up of the step is read against these: the step cannot scale better
// than the host lets pure arithmetic scale, and its memory-bound parts no better than the stream.
//
// build: gcc -O2 -fopenmp scripts/threads/core_probe.c -o core_probe
// usage: core_probe [SECONDS_PER_PROBE]       (default 0.3)
// prints: compute 1t RATE 2t RATE ratio R / stream 1t RATE 2t RATE ratio R (one line)
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

// 32 independent multiply-add chains on doubles: enough for the core's floating-point pipes to be
// the limit, not a chain's latency, so that a second thread on the same physical core (an SMT
// sibling) has no idle pipe to take and the pair gets about 1x, where two cores get 2x.
// Returns operations done.
enum { chains = 32 };
static double compute_for(double seconds, double* sink) {
    double x[chains];
    for (int k = 0; k < chains; ++k) x[k] = 1.0 + 0.01 * k;
    const double a = 0.999999, b = 1e-7;
    double ops = 0.0;
    const double start = omp_get_wtime();
    while (omp_get_wtime() - start < seconds) {
        for (int i = 0; i < 100000; ++i)
            for (int k = 0; k < chains; ++k) x[k] = x[k] * a + b;
        ops += 2.0 * chains * 100000;
    }
    double s = 0.0;
    for (int k = 0; k < chains; ++k) s += x[k];
    *sink += s;
    return ops;
}

// Reads and writes a buffer far larger than the L3 (64 MiB a thread), a line at a time. Returns bytes moved.
static double stream_for(double seconds, double* buffer, size_t n, double* sink) {
    double bytes = 0.0;
    const double start = omp_get_wtime();
    while (omp_get_wtime() - start < seconds) {
        for (size_t i = 0; i < n; i += 8) buffer[i] += 1.0;
        bytes += (double)n * sizeof(double) * 2.0;
    }
    *sink += buffer[0];
    return bytes;
}

// Runs the probe on `threads` threads at once; returns the total rate.
static double rate(int threads, int stream, double seconds, double** buffers, size_t n) {
    double total = 0.0, sink = 0.0;
#pragma omp parallel num_threads(threads) reduction(+ : total, sink)
    {
        const int t = omp_get_thread_num();
        total += stream ? stream_for(seconds, buffers[t], n, &sink) : compute_for(seconds, &sink);
    }
    if (sink == 12345.678) printf("%g\n", sink);  // keeps the work from being dropped
    return total / seconds;
}

int main(int argc, char** argv) {
    const double seconds = argc > 1 ? atof(argv[1]) : 0.3;
    const size_t n = (size_t)64 << 17;  // 64 MiB of doubles a thread
    double* buffers[2];
    for (int t = 0; t < 2; ++t) {
        buffers[t] = malloc(n * sizeof(double));
        if (!buffers[t]) return 1;
        for (size_t i = 0; i < n; ++i) buffers[t][i] = 0.0;
    }
    const double c1 = rate(1, 0, seconds, buffers, n), c2 = rate(2, 0, seconds, buffers, n);
    const double s1 = rate(1, 1, seconds, buffers, n), s2 = rate(2, 1, seconds, buffers, n);
    printf("compute 1t %.3e 2t %.3e ratio %.3f / stream 1t %.3e B/s 2t %.3e B/s ratio %.3f\n", c1, c2, c2 / c1, s1, s2,
           s2 / s1);
    free(buffers[0]);
    free(buffers[1]);
    return 0;
}
