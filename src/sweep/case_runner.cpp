#include "sweep/case_runner.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>

#include <fmt/format.h>

#include "analysis/housner_rocking.hpp"
#include "analysis/housner_sine_response.hpp"
#include "analysis/rocking_mode.hpp"
#include "io/history_writer.hpp"
#include "io/output_file.hpp"
#include "io/input_error.hpp"
#include "io/overrides.hpp"
#include "io/scenario.hpp"
#include "io/state_file.hpp"
#include "world/response_monitor.hpp"
#include "world/simulation.hpp"
#include "world/simulation_error.hpp"
#include "world/world_state.hpp"

namespace blockdem::sweep {
namespace {

/// Thrown from the step callback to end a run whose blocks have all gone over.
struct RunStoppedEarly {};

std::vector<std::string> as_set_arguments(const std::vector<Assignment>& assignments) {
    std::vector<std::string> out;
    for (const auto& a : assignments) out.push_back(a.key + "=" + a.value);
    return out;
}

void start_case_from_state(World& w, const std::filesystem::path& file, const std::filesystem::path& scenario) {
    const StateFile state(file);
    if (auto mismatch = state_mismatch(w, state.world()))
        throw InputError({file.string(), "", 0, 0},
                         fmt::format("the state does not belong to scenario {}: {}", scenario.string(), *mismatch));
    start_from_state(w, state.world());
}

// The scenario of one case: the unvaried TOML, the assignments, then the record (which replaces
// the whole horizontal motion, since a sine's keys mean nothing to a record).
toml::table case_root(const SweepScenario& scenario, const SweepPlan& plan, const SweepCase& c) {
    toml::table root = scenario.root;
    apply_overrides(root, as_set_arguments(c.assignments));
    if (c.record) {
        if (auto* motion = root["table_motion"].as_table()) motion->erase("horizontal");
        apply_overrides(root, as_set_arguments(record_assignments(plan.suite, c)));
    }
    return root;
}

World build_case_world(const SweepScenario& scenario, const SweepPlan& plan, const SweepCase& c) {
    const toml::table root = case_root(scenario, plan, c);
    const Model model = read_model(root, scenario.file.string(), scenario.file.parent_path());
    World w;
    try {
        w = build_world(model);
    } catch (const ModelError& e) {
        throw InputError({scenario.file.string(), "", 0, 0}, e.what());
    }
    // [simulation] initial_state: every case starts from the settled state (settle once, shake
    // many times). The file is read for each case: a sweep may vary it.
    if (const auto state = root.at_path("simulation.initial_state").value<std::string>())
        start_case_from_state(w, scenario.file.parent_path() / *state, scenario.file);
    return w;
}

RockingWindow window_for(const World& w) {
    const auto* sine = std::get_if<SineMotion>(&w.table_motion.horizontal);
    const bool harmonic = sine && std::holds_alternative<RestMotion>(w.table_motion.vertical);
    return harmonic ? rocking_window(*sine, w.settings.duration_s) : RockingWindow{};
}

// Past halfway between the critical angle and lying on its side, a block is down for good.
bool all_blocks_down(const World& w, const ResponseMonitor& monitor) {
    bool any = false;
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        if (w.bodies.kind[i] != BodyKind::dynamic) continue;
        const BodyResponse& r = monitor.responses()[i];
        const double theta = w.bodies.rotation_rad[i];
        const double alpha = theta > 0.0 ? r.alpha_ccw_rad : r.alpha_cw_rad;
        if (std::abs(theta) < 0.5 * (alpha + 0.5 * std::numbers::pi)) return false;
        any = true;
    }
    return any;
}

BodyOutcome outcome_of(const ResponseMonitor& monitor, const RockingModeObserver& modes, std::size_t i,
                       const ClassifiedOutcome& classified) {
    const BodyResponse& r = monitor.responses()[i];
    BodyOutcome o;
    o.outcome = to_string(classified.outcome);
    o.outcome_time_s = classified.time_s;
    o.failed = is_failure(classified.outcome);
    o.overturned = r.overturned();
    o.overturning_time_s = o.overturned ? r.last_crossing_s : -1.0;
    o.peak_rotation_rad = r.peak_abs_rotation_rad;
    o.peak_sliding_m = r.peak_abs_base_slip_m;
    o.residual_sliding_m = r.base_slip_m;
    RockingSignal signal = modes.signal_of(i);
    signal.rocking_threshold_rad = r.rocking_threshold_rad;
    signal.overturned = r.overturned();
    signal.slid = r.slid();
    signal.rocked = r.rocked();
    const RockingClassification mode = classify_rocking_mode(signal);
    o.mode = to_string(mode.mode);
    o.rocking_period_ratio = mode.period_ratio;
    o.phase_lag_deg = mode.phase_lag_rad * 180.0 / std::numbers::pi;
    return o;
}

void run_dem(World& w, const SweepScenario& scenario, const SweepCase& c, const CaseOptions& options,
             const std::atomic<bool>* cancel, CaseResult& result) {
    ResponseMonitor monitor(w);
    RockingModeObserver modes(w, window_for(w));
    RunOptions run;
    std::unique_ptr<HistoryWriter> history;
    if (!options.histories_dir.empty()) {
        const auto dir = options.histories_dir / std::to_string(c.id);
        std::filesystem::create_directories(dir);
        history = std::make_unique<HistoryWriter>(dir / "history.csv", w);
        run.recorders.push_back(history.get());
    }
    run.on_step = [&](const World& world) {
        monitor.observe(world);
        modes.observe(world);
        if ((world.step_index & 1023) == 0 && cancel && cancel->load(std::memory_order_relaxed)) throw CaseCancelled{};
        if (options.stop_when_overturned && all_blocks_down(world, monitor)) throw RunStoppedEarly{};
    };
    try {
        run_simulation(w, run);
        result.status = "completed";
    } catch (const CaseCancelled&) {
        // Only finished cases leave files: a rerun does this one again from the start.
        if (history) {
            history.reset();
            std::error_code ignored;
            std::filesystem::remove_all(options.histories_dir / std::to_string(c.id), ignored);
        }
        throw;
    } catch (const RunStoppedEarly&) {
        result.status = "completed";
    } catch (const SimulationError& e) {
        result.status = "failed";
        result.error = e.what();
        return;
    }
    const std::vector<ClassifiedOutcome> classified = classify_outcomes(monitor.records(w), monitor.thresholds());
    for (std::size_t k = 0; k < scenario.body_names.size(); ++k) {
        for (std::size_t i = 0; i < w.bodies.size(); ++i)
            if (w.bodies.name[i] == scenario.body_names[k] && w.bodies.kind[i] == BodyKind::dynamic)
                result.bodies[k] = outcome_of(monitor, modes, i, classified[i]);
    }
}

// The one dynamic block as Housner's rectangle: half sizes from its corners.
HousnerBlock housner_block_of(const World& w, std::size_t& body, const CaseOptions& options) {
    std::size_t found = 0;
    for (std::size_t i = 0; i < w.bodies.size(); ++i)
        if (w.bodies.kind[i] == BodyKind::dynamic) {
            body = i;
            ++found;
        }
    if (found != 1) throw std::invalid_argument("--solver housner needs exactly one dynamic body");
    if (w.bodies.vertex_count[body] != 4) throw std::invalid_argument("--solver housner needs a rectangular block");
    if (w.settings.tilt_rad != 0.0 || w.settings.tilt_rate_rad_s != 0.0)
        throw std::invalid_argument("--solver housner models a level table; this scenario tilts gravity (simulation.tilt_deg, "
                                    "tilt_rate_deg_s or a gravity vector)");
    HousnerBlock b;
    b.half_width_m = 0.0;
    b.half_height_m = 0.0;
    for (std::uint32_t k = 0; k < 4; ++k) {
        const Vec2 v = w.bodies.local_vertices_m[w.bodies.vertex_begin[body] + k];
        b.half_width_m = std::max(b.half_width_m, std::abs(v.x));
        b.half_height_m = std::max(b.half_height_m, std::abs(v.y));
    }
    b.gravity_m_s2 = w.settings.gravity_m_s2;
    b.restitution = options.housner_restitution;
    return b;
}

void run_housner(const World& w, const SweepScenario& scenario, const CaseOptions& options, CaseResult& result) {
    std::size_t body = 0;
    const HousnerBlock block = housner_block_of(w, body, options);
    const RockingResult r = housner_rocking(block, w.table_motion.horizontal, 0.0, 0.0, w.settings.duration_s, options.housner_dt_s);
    const double alpha = block.alpha_rad();
    BodyOutcome o;
    o.overturned = r.overturned;
    o.peak_rotation_rad = r.peak_abs_theta_rad;
    if (r.overturned)
        for (std::size_t k = 1; k < r.history.size(); ++k)
            if (std::abs(r.history[k].theta_rad) >= alpha && std::abs(r.history[k - 1].theta_rad) < alpha)
                o.overturning_time_s = r.history[k].time_s;
    RockingSignal signal = housner_rocking_signal(r, w.table_motion.horizontal, window_for(w));
    signal.rocking_threshold_rad = 0.01 * alpha;  // as the DEM's monitor
    signal.overturned = r.overturned;
    signal.rocked = r.peak_abs_theta_rad >= signal.rocking_threshold_rad;
    // (Housner's block neither slides nor leaves its base: only these three outcomes.)
    const Outcome outcome = r.overturned ? Outcome::overturned : signal.rocked ? Outcome::rocked : Outcome::stable;
    o.outcome = to_string(outcome);
    o.outcome_time_s = r.overturned ? o.overturning_time_s : -1.0;
    o.failed = is_failure(outcome);
    const RockingClassification mode = classify_rocking_mode(signal);
    o.mode = to_string(mode.mode);
    o.rocking_period_ratio = mode.period_ratio;
    o.phase_lag_deg = mode.phase_lag_rad * 180.0 / std::numbers::pi;
    result.status = "completed";
    for (std::size_t k = 0; k < scenario.body_names.size(); ++k)
        if (scenario.body_names[k] == w.bodies.name[body]) result.bodies[k] = o;
}

}  // namespace

namespace {

SweepScenario sweep_scenario_from(LoadedScenario loaded, const std::filesystem::path& file) {
    SweepScenario s;
    s.file = file;
    s.root = loaded.root;
    // A bad initial state is bad input of the sweep, found before any case runs.
    if (!loaded.initial_state.empty()) start_case_from_state(loaded.world, loaded.initial_state, file);
    for (std::size_t i = 0; i < loaded.world.bodies.size(); ++i)
        if (loaded.world.bodies.kind[i] == BodyKind::dynamic) s.body_names.push_back(loaded.world.bodies.name[i]);
    return s;
}

}  // namespace

SweepScenario load_sweep_scenario(const std::filesystem::path& file) {
    return sweep_scenario_from(load_scenario(file, {}), file);
}

SweepScenario load_sweep_scenario(toml::table root, const std::filesystem::path& file) {
    return sweep_scenario_from(load_scenario(std::move(root), file, {}), file);
}

namespace {

// Whether an input error is about one of the axis's keys: the error names the key or a table on
// its path (an unknown key is named at its first unknown part: 'nosuch' for nosuch.key).
bool names_axis(const InputError& e, const SweepAxis& axis) {
    const std::string& at = e.where().key;
    if (at.empty()) return false;
    for (const std::string& key : axis.keys)
        if (key == at || key.starts_with(at + ".")) return true;
    return false;
}

}  // namespace

void check_axes_readable(const SweepScenario& scenario, const SweepPlan& plan) {
    const SweepCase first = make_case(plan, 0);
    std::size_t column = 0;  // the axis's first assignment in a case's list
    for (const SweepAxis& axis : plan.axes) {
        std::string first_error;
        // Refused only when every value fails on the axis's own keys: a failure on another key
        // (another axis's first value, the first record) says nothing of this axis.
        bool all_fail_here = true;
        for (std::size_t p = 0; p < axis.points.size() && all_fail_here; ++p) {
            SweepCase c = first;
            for (std::size_t j = 0; j < axis.keys.size(); ++j) c.assignments[column + j].value = axis.points[p][j];
            try {
                (void)read_model(case_root(scenario, plan, c), scenario.file.string(), scenario.file.parent_path());
                all_fail_here = false;
            } catch (const InputError& e) {
                all_fail_here = names_axis(e, axis);
                if (first_error.empty()) first_error = e.problem();
            } catch (const std::exception&) {
                all_fail_here = false;
            }
        }
        if (all_fail_here)
            throw InputError({scenario.file.string(), axis.keys.front(), 0, 0},
                             fmt::format("no value of the varied key can be read into the scenario (the first: {})", first_error));
        column += axis.keys.size();
    }
}

CaseResult run_case(const SweepScenario& scenario, const SweepPlan& plan, const SweepCase& c,
                    const CaseOptions& options, const std::atomic<bool>* cancel) {
    const auto started = std::chrono::steady_clock::now();
    CaseResult result;
    result.id = c.id;
    result.bodies.resize(scenario.body_names.size());
    try {
        World w = build_case_world(scenario, plan, c);
        result.table_pga_m_s2 = peak_acceleration(w.table_motion.horizontal);
        if (options.solver == Solver::housner)
            run_housner(w, scenario, options, result);
        else
            run_dem(w, scenario, c, options, cancel, result);
    } catch (const CaseCancelled&) {
        throw;
    } catch (const OutputError&) {
        throw;  // a full disk stops the sweep; it is not this case's fault
    } catch (const SimulationError& e) {
        // Started and failed before the shaking: an assembly that did not settle.
        result.status = "failed";
        result.error = e.what();
        result.bodies.assign(scenario.body_names.size(), std::nullopt);
    } catch (const std::exception& e) {
        // Bad input for this case (a value out of range, a missing record): recorded, not fatal.
        result.status = "error";
        result.error = e.what();
        result.bodies.assign(scenario.body_names.size(), std::nullopt);
    }
    result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

}  // namespace blockdem::sweep
