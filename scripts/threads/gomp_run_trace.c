// Times each run a thread takes in the OpenMP loops of a program (GCC's libgomp, schedule(dynamic)),
// for run_balance.py: preloaded, it wraps GOMP_parallel (a region's start and end, named by its
// outlined function) and the dynamic loop's start and next (a run handed out, with its first item),
// and writes one line an event to the file GOMP_TRACE names when the program exits:
//   tsc  outlined-function  kind (0 region start, 1 run handed out, 2 no run left, 9 region end)  thread  first  end
// Build and use (docs/performance.md, "Branch body5"):
//   gcc -O2 -shared -fPIC -fopenmp scripts/threads/gomp_run_trace.c -o gomp_run_trace.so -ldl
//   OMP_NUM_THREADS=1 GOMP_TRACE=trace.txt LD_PRELOAD=./gomp_run_trace.so ./step_wall_3d 10000 20 > out.txt
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <x86intrin.h>
typedef struct { unsigned long long t; void* fn; int kind; int thread; long start, end; } Ev;
#define MAXEV 8000000
static Ev* evs; static long nev;
static __thread void* cur_fn; static __thread int tid;
static void* region_fn;  // set by GOMP_parallel (serial)
int omp_get_thread_num(void);
static void rec(int kind, long s, long e) {
  long k = __atomic_fetch_add(&nev, 1, __ATOMIC_RELAXED);
  if (k < MAXEV) { evs[k].t = __rdtsc(); evs[k].fn = region_fn; evs[k].kind = kind; evs[k].thread = omp_get_thread_num(); evs[k].start = s; evs[k].end = e; }
}
static void dump(void) {
  const char* p = getenv("GOMP_TRACE"); if (!p) return;
  FILE* f = fopen(p, "w");
  for (long k = 0; k < nev && k < MAXEV; ++k) fprintf(f, "%llu %p %d %d %ld %ld\n", evs[k].t, evs[k].fn, evs[k].kind, evs[k].thread, evs[k].start, evs[k].end);
  fclose(f);
}
__attribute__((constructor)) static void init(void) { evs = malloc(sizeof(Ev) * MAXEV); atexit(dump); }
void GOMP_parallel(void (*fn)(void*), void* data, unsigned n, unsigned flags) {
  static void (*real)(void (*)(void*), void*, unsigned, unsigned);
  if (!real) real = dlsym(RTLD_NEXT, "GOMP_parallel");
  region_fn = (void*)fn; rec(0, 0, 0);
  real(fn, data, n, flags);
  rec(9, 0, 0);
}
bool GOMP_loop_nonmonotonic_dynamic_start(long a, long b, long c, long d, long* s, long* e) {
  static bool (*real)(long, long, long, long, long*, long*);
  if (!real) real = dlsym(RTLD_NEXT, "GOMP_loop_nonmonotonic_dynamic_start");
  bool r = real(a, b, c, d, s, e); rec(r ? 1 : 2, r ? *s : -1, r ? *e : -1); return r;
}
bool GOMP_loop_nonmonotonic_dynamic_next(long* s, long* e) {
  static bool (*real)(long*, long*);
  if (!real) real = dlsym(RTLD_NEXT, "GOMP_loop_nonmonotonic_dynamic_next");
  bool r = real(s, e); rec(r ? 1 : 2, r ? *s : -1, r ? *e : -1); return r;
}
