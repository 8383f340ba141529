// `blockdem bench [--scene wall|keyed_wall|bonded_wall|slope|rockfill] [--sizes 100,1000] [--threads 1,2] ...`
// Throughput of the time step on the benchmark scenes (docs/performance.md): block-steps/s,
// contact-steps/s, time per step split by phase, memory per block, speedup with threads. The
// stepping loop alone is timed (scene building and --warmup steps are not), and each case is
// repeated and its fastest run kept: on a shared machine the minimum is the least disturbed.
// The thread counts of one size run in turn on copies of the same warmed-up world.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "apps/blockdem/commands.hpp"
#include "apps/blockdem/option_checks.hpp"
#include "io/output_file.hpp"
#include "scenes/assemblies.hpp"
#include "world/step.hpp"

namespace blockdem::cli {
namespace {

struct BenchOptions {
    std::vector<std::string> scenes{"wall"};
    std::vector<int> sizes{100, 1000, 10000};
    std::vector<int> threads{1, 2};
    double work = 3e6;          ///< block-steps per timed run (steps = work / N, 3 to 5000)
    int repeats = 3;
    int warmup = 5;             ///< untimed steps after building (contacts close as the blocks settle)
    double rounding_m = 0.0;    ///< [m] [contact] rounding of the scene's corners (0: sharp, the scenes' own)
    double idle_wait_s = 0.0;   ///< wait up to this long for the CPUs to be 90% idle before each run
    std::string markdown;
};

struct BenchResult {
    std::string scene;
    int threads = 1;
    std::size_t bodies = 0;
    std::int64_t steps = 0;
    double wall_s = INFINITY;   ///< [s] fastest run
    double cpu_s = 0.0;         ///< [s] CPU time of the fastest run, all threads (below wall_s x threads: contended)
    StepTimings phases;         ///< of the fastest run
    std::size_t pairs = 0;      ///< touching pairs at the end
    std::size_t points = 0;     ///< contact points at the end
    std::size_t world_bytes = 0;
    double busy = 0.0;          ///< CPU busy fraction before the fastest run
};

// Fraction of the CPUs busy over half a second (/proc/stat), -1 if unreadable.
double cpu_busy_fraction() {
    auto read = [] {
        std::ifstream in("/proc/stat");
        std::string cpu;
        double v[8] = {};
        in >> cpu;
        for (double& x : v) in >> x;
        double total = 0.0;
        for (double x : v) total += x;
        return std::pair{total, v[3] + v[4]};
    };
    const auto [t0, i0] = read();
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    const auto [t1, i1] = read();
    return t1 > t0 ? 1.0 - (i1 - i0) / (t1 - t0) : -1.0;
}

double wait_for_idle(double max_wait_s) {
    const auto start = std::chrono::steady_clock::now();
    double busy = cpu_busy_fraction();
    while (busy > 0.1 && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < max_wait_s)
        busy = cpu_busy_fraction();
    return busy;
}

Model make_scene(const std::string& scene, int n) {
    if (scene == "wall") return scenes::s3_wall_scene(n, 1e9);
    if (scene == "slope") return scenes::rock_slope_scene(n, 1e9);
    if (scene == "rockfill") return scenes::rockfill_scene(n, 1e9);
    if (scene == "keyed_wall") return scenes::keyed_wall_scene(n, 1e9);
    if (scene == "bonded_wall") return scenes::bonded_wall_scene(n, 1e9);
    throw std::invalid_argument("unknown scene '" + scene + "' (wall, keyed_wall, bonded_wall, slope, rockfill)");
}


// One world per thread count, copied from one warmed-up world, so that every thread count times
// the same steps from the same state (the results are bit-identical: parallel.hpp). Memory is
// one world per thread count: measure a single world's peak with a single --threads value.
struct TimedWorld {
    World world;
    BenchResult result;
};

std::vector<TimedWorld> prepare_cases(const std::string& scene, int n, const BenchOptions& o) {
    if (o.threads.empty()) throw std::invalid_argument("--threads: give at least one thread count");
    set_step_threads(o.threads.front());
    Model model = make_scene(scene, n);
    model.contact.rounding_m = o.rounding_m;
    World w = build_world(model);
    for (int i = 0; i < o.warmup; ++i) step(w);
    BenchResult r;
    r.scene = scene;
    r.bodies = w.bodies.size() - 1;  // the table is not a block
    r.steps = static_cast<std::int64_t>(std::clamp(std::round(o.work / static_cast<double>(r.bodies)), 3.0, 5000.0));
    // Measured once, here: a copy's vectors have no spare capacity, so measuring each copy
    // would report different sizes for the same world.
    r.world_bytes = memory_bytes(w);
    std::vector<TimedWorld> cases;
    for (std::size_t i = 0; i < o.threads.size(); ++i) {
        r.threads = o.threads[i];
        // The last case takes the world itself: with one thread count, one world in memory.
        if (i + 1 < o.threads.size())
            cases.push_back({w, r});
        else
            cases.push_back({std::move(w), r});
    }
    return cases;
}

// Times one run of c.result.steps steps; keeps it if it is the fastest so far.
void time_run(TimedWorld& c, const BenchOptions& o) {
    BenchResult& r = c.result;
    World& w = c.world;
    set_step_threads(r.threads);
    const double busy = o.idle_wait_s > 0.0 ? wait_for_idle(o.idle_wait_s) : 0.0;
    w.timings = StepTimings{};
    w.timings.enabled = true;
    const std::clock_t cpu_start = std::clock();
    const auto start = std::chrono::steady_clock::now();
    for (std::int64_t s = 0; s < r.steps; ++s) step(w);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (wall < r.wall_s) {
        r.wall_s = wall;
        r.cpu_s = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
        r.phases = w.timings;
        r.busy = busy;
    }
}

void count_contacts(TimedWorld& c) {
    BenchResult& r = c.result;
    r.pairs = r.points = 0;
    for (const PairContact& pair : c.world.contacts) {
        r.pairs += pair.count > 0 ? 1 : 0;
        r.points += pair.count;
    }
}

std::string phase_split(const StepTimings& t) {
    const double sum = t.geometry_s + t.broad_phase_s + t.contacts_s + t.bodies_s + t.positions_s;
    auto pct = [&](double x) { return 100.0 * x / std::max(sum, 1e-300); };
    return fmt::format("{:.0f} / {:.0f} / {:.0f} / {:.0f} / {:.0f}", pct(t.geometry_s), pct(t.broad_phase_s),
                       pct(t.contacts_s), pct(t.bodies_s), pct(t.positions_s));
}

std::string row(const BenchResult& r, double one_thread_wall_s) {
    const double per_step = r.wall_s / static_cast<double>(r.steps);
    const double speedup = one_thread_wall_s > 0.0 ? one_thread_wall_s / per_step : NAN;
    return fmt::format("| {} | {} | {} | {} | {:.4g} | {:.4g} | {:.3g} | {:.3g} | {} | {} | {:.3g} | {} | {:.0f} | {:.2f} |",
                       r.scene, r.bodies, r.threads, r.steps, 1e3 * per_step, 1e3 * r.cpu_s / static_cast<double>(r.steps), static_cast<double>(r.bodies) / per_step,
                       static_cast<double>(r.points) / per_step, r.pairs, r.points,
                       std::isnan(speedup) ? 1.0 : speedup, phase_split(r.phases),
                       static_cast<double>(r.world_bytes) / static_cast<double>(r.bodies), r.busy);
}

void run_bench(const BenchOptions& o) {
    std::ostringstream table;
    table << "| scene | blocks | threads | steps | ms/step (min) | CPU ms/step | block-steps/s | contact-steps/s | touching pairs | "
             "contact points | speedup vs 1 thread | geometry / broad / contacts / bodies / positions [%] | "
             "world bytes/block | CPU busy before |\n"
          << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    fmt::print("{}", table.str());
    for (const std::string& scene : o.scenes)
        for (int n : o.sizes) {
            std::vector<TimedWorld> cases = prepare_cases(scene, n, o);
            // The thread counts take turns, repeat by repeat: a slow spell of a shared machine
            // then slows all of them, not just one, and the speedup compares like with like.
            for (int rep = 0; rep < o.repeats; ++rep)
                for (TimedWorld& c : cases) time_run(c, o);
            double one_thread = 0.0;
            for (TimedWorld& c : cases) {
                count_contacts(c);
                const BenchResult& r = c.result;
                const std::string line = row(r, r.threads == 1 ? 0.0 : one_thread);
                if (r.threads == 1) one_thread = r.wall_s / static_cast<double>(r.steps);
                fmt::print("{}\n", line);
                table << line << '\n';
            }
            std::fflush(stdout);
        }
    if (!o.markdown.empty()) write_output_file(o.markdown, table.str());
}

}  // namespace

void add_bench_command(CLI::App& app) {
    auto* cmd = app.add_subcommand("bench", "Time the step on the benchmark scenes (docs/performance.md)");
    auto o = std::make_shared<BenchOptions>();
    cmd->add_option("--scene", o->scenes, "wall (scene S3), keyed_wall (S3 of concave keyed bricks), bonded_wall (S3 with bonded per-length joints), slope (jointed rock), rockfill (Voronoi); repeatable")
        ->delimiter(',')
        ->capture_default_str();
    cmd->add_option("--sizes", o->sizes, "numbers of blocks, e.g. 100,1000,10000")
        ->delimiter(',')
        ->check(whole_number_in(1, 100000000))
        ->capture_default_str();
    cmd->add_option("--threads", o->threads, "OpenMP thread counts, e.g. 1,2 (1 first gives the speedup)")
        ->delimiter(',')
        ->check(whole_number_in(1, max_threads))
        ->capture_default_str();
    cmd->add_option("--work", o->work, "block-steps per timed run (steps = work / blocks, 3 to 5000)")->capture_default_str();
    cmd->add_option("--warmup", o->warmup, "untimed steps before timing (same for every size: same state)")
        ->capture_default_str();
    cmd->add_option("--rounding", o->rounding_m, "corner radius [m] of every block ([contact] rounding); 0: sharp")
        ->check(finite_non_negative())
        ->capture_default_str();
    cmd->add_option("--repeats", o->repeats, "timed runs per case; the fastest is reported")->capture_default_str();
    cmd->add_option("--idle-wait", o->idle_wait_s, "wait up to this many seconds for idle CPUs before each run")
        ->capture_default_str();
    cmd->add_option("--markdown", o->markdown, "also write the table to this file");
    cmd->callback([o] { run_bench(*o); });
}

}  // namespace blockdem::cli
