#include "study/convergence_verdict.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

namespace blockdem {
namespace {

using Values = std::vector<std::optional<double>>;
using Words = std::vector<std::optional<std::string>>;

// The continuous quantities, their floors, and whether they describe the response of a body
// that is still standing (after overturning, peak rotation and slip describe the fall).
struct QuantityDef {
    const char* name;
    double ConvergenceTolerance::*floor;
    bool standing_response;
};
constexpr QuantityDef continuous_quantities[] = {
    {"peak_rotation_rad", &ConvergenceTolerance::floor_rotation_rad, true},
    {"peak_slip_m", &ConvergenceTolerance::floor_slip_m, true},
    {"final_slip_m", &ConvergenceTolerance::floor_slip_m, true},
    {"overturning_time_s", &ConvergenceTolerance::floor_time_s, false},
};

std::optional<double> value_of(const BodyOutcome& b, const std::string& quantity) {
    if (quantity == "peak_rotation_rad") return b.peak_rotation_rad;
    if (quantity == "peak_slip_m") return b.peak_slip_m;
    if (quantity == "final_slip_m") return b.final_slip_m;
    return b.overturned ? b.overturning_time_s : std::nullopt;
}

std::optional<std::string> word_of(const BodyOutcome& b, const std::string& quantity) {
    if (quantity == "overturned") return std::string(b.overturned ? "yes" : "no");
    return b.outcome;
}

double get_number(const nlohmann::json& j, const char* key, const std::string& where) {
    if (!j.contains(key) || !j[key].is_number()) throw std::runtime_error(fmt::format("{}: no number '{}'", where, key));
    return j[key].get<double>();
}

// The runs that completed, each with a name -> body index.
struct Table {
    const RunOutcome* run;
    std::map<std::string, std::size_t> index;
};

std::vector<Table> tables_of(const std::vector<RunOutcome>& runs) {
    std::vector<Table> tables;
    for (const RunOutcome& r : runs) {
        if (r.status != "completed") continue;
        Table t{&r, {}};
        for (std::size_t i = 0; i < r.bodies.size(); ++i) t.index[r.bodies[i].name] = i;
        tables.push_back(std::move(t));
    }
    return tables;
}

const BodyOutcome& body_in(const Table& t, const std::string& name) {
    const auto it = t.index.find(name);
    if (it == t.index.end()) throw std::runtime_error(fmt::format("run {} has no dynamic body '{}'", t.run->label, name));
    return t.run->bodies[it->second];
}

std::vector<const BodyOutcome*> bodies_named(const std::vector<Table>& tables, const std::string& name) {
    std::vector<const BodyOutcome*> out;
    for (const Table& t : tables) out.push_back(&body_in(t, name));
    return out;
}

bool any_overturned(const std::vector<const BodyOutcome*>& bodies) {
    return std::any_of(bodies.begin(), bodies.end(), [](const BodyOutcome* b) { return b->overturned; });
}
bool all_overturned(const std::vector<const BodyOutcome*>& bodies) {
    return std::all_of(bodies.begin(), bodies.end(), [](const BodyOutcome* b) { return b->overturned; });
}

// Whether a continuous quantity is judged over these runs: the response of a standing body
// when it stood in all of them, the overturning time when it overturned in all of them.
bool judged_over(const QuantityDef& q, const std::vector<const BodyOutcome*>& bodies) {
    return q.standing_response ? !any_overturned(bodies) : all_overturned(bodies);
}

QuantityComparison compare_continuous(const QuantityDef& q, const std::vector<const BodyOutcome*>& runs,
                                      const ConvergenceTolerance& tol) {
    QuantityComparison c;
    c.quantity = q.name;
    const double floor = tol.*q.floor;
    for (const BodyOutcome* b : runs) c.values.push_back(value_of(*b, q.name));
    for (std::size_t i = 1; i < c.values.size(); ++i) {
        const auto& a = c.values[i - 1];
        const auto& b = c.values[i];
        c.changes.push_back(a && b ? std::optional(relative_change(*a, *b, floor)) : std::nullopt);
    }
    if (c.values.front() && c.values.back()) c.base_error = relative_change(*c.values.front(), *c.values.back(), floor);
    if (c.values.size() == 3 && c.values[0] && c.values[1] && c.values[2]) {
        const double d01 = std::abs(*c.values[1] - *c.values[0]);
        const double d12 = std::abs(*c.values[2] - *c.values[1]);
        if (d01 > 0.0 && d12 > 0.0) {
            c.change_ratio = d01 / d12;
            if (*c.change_ratio > 1.0) c.observed_order = std::log2(*c.change_ratio);
        }
    }
    // The last two runs decide: the finest answer is the one to believe.
    const std::vector<const BodyOutcome*> last(runs.end() - std::min<std::size_t>(2, runs.size()), runs.end());
    c.judged = judged_over(q, last) && !c.changes.empty() && c.changes.back().has_value();
    c.converged = !c.judged || *c.changes.back() <= tol.rtol;
    return c;
}

QuantityComparison compare_discrete(const std::string& quantity, const std::vector<const BodyOutcome*>& runs) {
    QuantityComparison c;
    c.quantity = quantity;
    c.discrete = true;
    for (const BodyOutcome* b : runs) c.words.push_back(word_of(*b, quantity));
    c.judged = c.words.size() >= 2 && c.words[c.words.size() - 2] && c.words.back();
    c.converged = !c.judged || *c.words[c.words.size() - 2] == *c.words.back();
    return c;
}

bool has_outcome_word(const std::vector<const BodyOutcome*>& runs) {
    return std::all_of(runs.begin(), runs.end(), [](const BodyOutcome* b) { return b->outcome.has_value(); });
}

std::vector<QuantityComparison> compare_over_dt(const std::vector<const BodyOutcome*>& runs, const ConvergenceTolerance& tol) {
    std::vector<QuantityComparison> out;
    for (const QuantityDef& q : continuous_quantities) out.push_back(compare_continuous(q, runs, tol));
    out.push_back(compare_discrete("overturned", runs));
    if (has_outcome_word(runs)) out.push_back(compare_discrete("outcome", runs));
    return out;
}

std::pair<double, double> min_max(const std::vector<double>& v) {
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    return {*lo, *hi};
}

EnsembleSpread spread_continuous(const QuantityDef& q, const std::vector<const BodyOutcome*>& members,
                                 const std::vector<const BodyOutcome*>& refinement, const ConvergenceTolerance& tol) {
    EnsembleSpread s;
    s.quantity = q.name;
    std::vector<double> v;
    for (const BodyOutcome* b : members)
        if (const auto x = value_of(*b, q.name)) v.push_back(*x);
    if (v.empty()) {
        s.judged = false;
        return s;
    }
    const auto [lo, hi] = min_max(v);
    double sum = 0.0;
    for (double x : v) sum += x;
    s.mean = sum / static_cast<double>(v.size());
    s.min = lo;
    s.max = hi;
    s.relative_spread = relative_change(lo, hi, tol.*q.floor);
    std::vector<double> over_dt;
    for (const BodyOutcome* b : refinement)
        if (const auto x = value_of(*b, q.name)) over_dt.push_back(*x);
    const double dt_range = over_dt.empty() ? 0.0 : min_max(over_dt).second - min_max(over_dt).first;
    if (dt_range > 0.0) s.dt_spread_ratio = (hi - lo) / dt_range;
    s.judged = judged_over(q, members) && v.size() >= 2;
    s.sensitive = s.judged && *s.relative_spread > tol.rtol;
    s.chaotic = s.sensitive && (dt_range == 0.0 || hi - lo >= tol.chaos_ratio * dt_range);
    return s;
}

EnsembleSpread spread_discrete(const std::string& quantity, const std::vector<const BodyOutcome*>& members) {
    EnsembleSpread s;
    s.quantity = quantity;
    s.discrete = true;
    for (const BodyOutcome* b : members)
        if (const auto w = word_of(*b, quantity); w && std::find(s.distinct.begin(), s.distinct.end(), *w) == s.distinct.end())
            s.distinct.push_back(*w);
    s.sensitive = s.chaotic = s.distinct.size() > 1;
    return s;
}

StiffnessComparison compare_stiffness_continuous(const QuantityDef& q, const std::vector<const BodyOutcome*>& runs,
                                                 std::size_t reference, const ConvergenceTolerance& tol) {
    StiffnessComparison c;
    c.quantity = q.name;
    for (const BodyOutcome* b : runs) c.values.push_back(value_of(*b, q.name));
    const auto& ref = c.values[reference];
    for (const auto& v : c.values)
        if (ref && v) c.max_change = std::max(c.max_change.value_or(0.0), relative_change(*ref, *v, tol.*q.floor));
    c.judged = judged_over(q, runs) && c.max_change.has_value();
    c.sensitive = c.judged && *c.max_change > tol.rtol;
    return c;
}

StiffnessComparison compare_stiffness_discrete(const std::string& quantity, const std::vector<const BodyOutcome*>& runs) {
    StiffnessComparison c;
    c.quantity = quantity;
    c.discrete = true;
    for (const BodyOutcome* b : runs) c.words.push_back(word_of(*b, quantity));
    c.sensitive = std::any_of(c.words.begin(), c.words.end(), [&](const auto& w) { return w != c.words.front(); });
    return c;
}

std::string describe_change(const QuantityComparison& q) {
    if (q.discrete)
        return fmt::format("{} changes from {} at dt/2 to {} at dt/4", q.quantity, *q.words[q.words.size() - 2], *q.words.back());
    return fmt::format("{} changes by {:.3g}% from dt/2 to dt/4", q.quantity, 100.0 * *q.changes.back());
}

std::string describe_spread(const EnsembleSpread& s) {
    if (s.discrete) return fmt::format("{} varies over the ensemble ({})", s.quantity, fmt::join(s.distinct, ", "));
    return fmt::format("{} spreads by {:.3g}% over the ensemble ({:.4g} to {:.4g})", s.quantity, 100.0 * *s.relative_spread,
                       *s.min, *s.max);
}

bool base_agrees(const QuantityComparison& q, const ConvergenceTolerance& tol) {
    if (!q.judged) return true;
    if (q.discrete) return q.words.front() == q.words.back();
    return q.base_error.has_value() ? *q.base_error <= tol.rtol : false;
}

void judge_body(BodyConvergence& b, const ConvergenceTolerance& tol) {
    for (const QuantityComparison& q : b.dt) {
        if (!q.converged) b.reasons.push_back(describe_change(q));
        if (!base_agrees(q, tol)) b.base_within_tolerance = false;
    }
    bool chaotic = false;
    for (const EnsembleSpread& s : b.ensemble) {
        if (s.sensitive) b.reasons.push_back(describe_spread(s));
        chaotic = chaotic || s.chaotic;
    }
    const bool dt_converged = std::all_of(b.dt.begin(), b.dt.end(), [](const QuantityComparison& q) { return q.converged; });
    b.verdict = chaotic ? Verdict::chaotic : dt_converged ? Verdict::converged : Verdict::not_converged;
    b.stiffness_sensitive = std::any_of(b.stiffness.begin(), b.stiffness.end(), [](const auto& s) { return s.sensitive; });
}

nlohmann::json optional_json(const std::optional<double>& v) {
    return v && std::isfinite(*v) ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

template <class T>
nlohmann::json optional_list(const std::vector<std::optional<T>>& v) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& x : v) a.push_back(x ? nlohmann::json(*x) : nlohmann::json(nullptr));
    return a;
}

nlohmann::json to_json(const QuantityComparison& q) {
    nlohmann::json j{{"quantity", q.quantity}, {"judged", q.judged}, {"converged", q.converged}};
    if (q.discrete) {
        j["values"] = optional_list(q.words);
        return j;
    }
    j["values"] = optional_list(q.values);
    j["relative_changes"] = optional_list(q.changes);
    j["base_relative_error"] = optional_json(q.base_error);
    j["change_ratio"] = optional_json(q.change_ratio);
    j["observed_order"] = optional_json(q.observed_order);
    return j;
}

nlohmann::json to_json(const EnsembleSpread& s) {
    nlohmann::json j{{"quantity", s.quantity}, {"judged", s.judged}, {"sensitive", s.sensitive}, {"chaotic", s.chaotic}};
    if (s.discrete) {
        j["values_seen"] = s.distinct;
        return j;
    }
    j["mean"] = optional_json(s.mean);
    j["min"] = optional_json(s.min);
    j["max"] = optional_json(s.max);
    j["relative_spread"] = optional_json(s.relative_spread);
    j["spread_over_dt_spread"] = optional_json(s.dt_spread_ratio);
    return j;
}

nlohmann::json to_json(const StiffnessComparison& c) {
    nlohmann::json j{{"quantity", c.quantity}, {"judged", c.judged}, {"sensitive", c.sensitive}};
    if (c.discrete) {
        j["values"] = optional_list(c.words);
        return j;
    }
    j["values"] = optional_list(c.values);
    j["max_relative_change"] = optional_json(c.max_change);
    return j;
}

template <class T>
nlohmann::json json_list(const std::vector<T>& items) {
    nlohmann::json a = nlohmann::json::array();
    for (const T& x : items) a.push_back(to_json(x));
    return a;
}

}  // namespace

std::string to_string(Verdict v) {
    switch (v) {
        case Verdict::converged: return "converged";
        case Verdict::not_converged: return "not converged";
        case Verdict::chaotic: return "chaotic";
    }
    return "?";
}

double relative_change(double a, double b, double floor) {
    const double scale = std::max({std::abs(a), std::abs(b), floor});
    return scale > 0.0 ? std::abs(b - a) / scale : 0.0;
}

namespace {

// A 3-D body (run/run_scenario_3d.cpp's summary): the tilt is the rocking whatever its axis, the
// slip a horizontal vector, compared by its length (a direction has no floor to judge it by), the
// overturning time and the outcome word as in 2-D (a summary written before 3-D had outcomes has
// none: it is left out, as for an older 2-D file).
BodyOutcome body_outcome_3d(const nlohmann::json& j, const std::string& where) {
    BodyOutcome b;
    b.name = j.value("name", std::string());
    b.peak_rotation_rad = get_number(j, "peak_tilt_rad", where);
    b.peak_slip_m = get_number(j, "peak_slip_m", where);
    if (!j.contains("slip_m") || !j["slip_m"].is_array() || j["slip_m"].size() != 2 || !j["slip_m"][0].is_number() ||
        !j["slip_m"][1].is_number())
        throw std::runtime_error(fmt::format("{}: no slip vector 'slip_m' [x, y]", where));
    b.final_slip_m = std::hypot(j["slip_m"][0].get<double>(), j["slip_m"][1].get<double>());
    b.overturned = j.value("overturned", false);
    if (j.contains("overturning_time_s") && j["overturning_time_s"].is_number())
        b.overturning_time_s = j["overturning_time_s"].get<double>();
    if (j.contains("outcome") && j["outcome"].is_string()) b.outcome = j["outcome"].get<std::string>();
    return b;
}

}  // namespace

nlohmann::json quantities_3d_json() {
    return {{"peak_rotation_rad", "summary.json peak_tilt_rad: the peak tilt about any horizontal axis"},
            {"peak_slip_m", "summary.json peak_slip_m: the peak length of the horizontal slip vector relative to the table"},
            {"final_slip_m", "the length of summary.json slip_m [x, y] at the end"},
            {"overturning_time_s", "summary.json overturning_time_s: the last time the tilt went past the toppling limit and stayed"},
            {"overturned", "summary.json overturned"}};
}

RunOutcome outcome_of_summary(const nlohmann::json& summary, const std::string& label) {
    RunOutcome run;
    run.label = label;
    run.status = summary.value("status", std::string("completed"));
    run.error = summary.value("error", std::string());
    run.dt_s = get_number(summary, "dt_s", "summary of run " + label);
    if (!summary.contains("bodies") || !summary["bodies"].is_array())
        throw std::runtime_error(fmt::format("summary of run {}: no 'bodies' list", label));
    const bool three_d = summary.value("dimension", 2) == 3;
    for (const auto& j : summary["bodies"]) {
        if (j.value("kind", std::string()) != "dynamic") continue;
        if (three_d) {
            run.bodies.push_back(body_outcome_3d(j, fmt::format("summary of run {}, body '{}'", label, j.value("name", std::string()))));
            continue;
        }
        BodyOutcome b;
        b.name = j.value("name", std::string());
        const std::string where = fmt::format("summary of run {}, body '{}'", label, b.name);
        b.peak_rotation_rad = get_number(j, "peak_abs_rotation_rad", where);
        b.peak_slip_m = get_number(j, "peak_abs_base_slip_m", where);
        b.final_slip_m = get_number(j, "final_base_slip_m", where);
        b.overturned = j.value("overturned", false);
        if (j.contains("overturning_time_s") && j["overturning_time_s"].is_number())
            b.overturning_time_s = j["overturning_time_s"].get<double>();
        // "outcome" (stable, rocked, slid, overturned, fell, left_model) is newer than the other
        // keys: compared when every run has it.
        if (j.contains("outcome") && j["outcome"].is_string()) b.outcome = j["outcome"].get<std::string>();
        run.bodies.push_back(std::move(b));
    }
    return run;
}

ConvergenceResult judge_convergence(const StudyRuns& runs, const ConvergenceTolerance& tol) {
    ConvergenceResult result;
    for (const auto* group : {&runs.refinement, &runs.ensemble, &runs.stiffness})
        for (const RunOutcome& r : *group)
            if (r.status != "completed") result.failed_runs.push_back(fmt::format("{}: {}", r.label, r.error));
    if (runs.refinement.empty()) throw std::runtime_error("a convergence study needs its refinement runs");
    const std::vector<Table> refinement = tables_of(runs.refinement);
    const bool refinement_complete = refinement.size() == runs.refinement.size();
    std::vector<Table> ensemble = tables_of(runs.ensemble);
    const std::vector<Table> stiffness = tables_of(runs.stiffness);
    const bool stiffness_complete = !runs.stiffness.empty() && stiffness.size() == runs.stiffness.size();
    if (stiffness_complete) result.stiffness_sensitive = false;
    // The base run is the ensemble's first member.
    if (!runs.ensemble.empty() && runs.refinement.front().status == "completed") ensemble.insert(ensemble.begin(), refinement.front());

    for (const BodyOutcome& base : runs.refinement.front().bodies) {
        BodyConvergence b;
        b.name = base.name;
        const auto over_dt = bodies_named(refinement, b.name);
        if (refinement_complete) b.dt = compare_over_dt(over_dt, tol);
        if (ensemble.size() >= 2 && refinement_complete) {
            const auto members = bodies_named(ensemble, b.name);
            for (const QuantityDef& q : continuous_quantities) b.ensemble.push_back(spread_continuous(q, members, over_dt, tol));
            b.ensemble.push_back(spread_discrete("overturned", members));
            if (has_outcome_word(members)) b.ensemble.push_back(spread_discrete("outcome", members));
            const auto n = std::count_if(members.begin(), members.end(), [](const BodyOutcome* m) { return m->overturned; });
            b.fraction_overturned = static_cast<double>(n) / static_cast<double>(members.size());
        }
        if (stiffness_complete) {
            const auto at = bodies_named(stiffness, b.name);
            const std::size_t reference = at.size() / 2;  // the 1 x run sits between 0.5 x and 2 x
            for (const QuantityDef& q : continuous_quantities) b.stiffness.push_back(compare_stiffness_continuous(q, at, reference, tol));
            b.stiffness.push_back(compare_stiffness_discrete("overturned", at));
            if (has_outcome_word(at)) b.stiffness.push_back(compare_stiffness_discrete("outcome", at));
        }
        judge_body(b, tol);
        if (!refinement_complete) {
            b.verdict = Verdict::not_converged;
            b.base_within_tolerance = false;
            b.reasons.push_back("a run of the time-step refinement failed");
        }
        if (b.stiffness_sensitive) result.stiffness_sensitive = true;
        result.bodies.push_back(std::move(b));
    }
    for (const BodyConvergence& b : result.bodies) {
        result.converged_count += b.verdict == Verdict::converged;
        result.not_converged_count += b.verdict == Verdict::not_converged;
        result.chaotic_count += b.verdict == Verdict::chaotic;
    }
    result.verdict = result.chaotic_count > 0 ? Verdict::chaotic
                     : result.not_converged_count > 0 || !refinement_complete ? Verdict::not_converged
                                                                              : Verdict::converged;
    return result;
}

nlohmann::json to_json(const ConvergenceResult& result, const ConvergenceTolerance& tol) {
    nlohmann::json j;
    j["verdict"] = to_string(result.verdict);
    j["counts"] = {{"converged", result.converged_count},
                   {"not_converged", result.not_converged_count},
                   {"chaotic", result.chaotic_count}};
    j["stiffness_sensitive"] = result.stiffness_sensitive ? nlohmann::json(*result.stiffness_sensitive) : nlohmann::json(nullptr);
    j["failed_runs"] = result.failed_runs;
    j["tolerance"] = {{"rtol", tol.rtol},
                      {"floors", {{"peak_rotation_rad", tol.floor_rotation_rad},
                                  {"peak_slip_m", tol.floor_slip_m},
                                  {"final_slip_m", tol.floor_slip_m},
                                  {"overturning_time_s", tol.floor_time_s}}},
                      {"chaos_ratio", tol.chaos_ratio},
                      {"relative_change", "|b - a| / max(|a|, |b|, floor)"}};
    nlohmann::json bodies = nlohmann::json::array();
    for (const BodyConvergence& b : result.bodies) {
        nlohmann::json jb{{"name", b.name},
                          {"verdict", to_string(b.verdict)},
                          {"base_within_tolerance", b.base_within_tolerance},
                          {"reasons", b.reasons},
                          {"dt", json_list(b.dt)}};
        if (!b.ensemble.empty()) {
            jb["ensemble"] = json_list(b.ensemble);
            jb["ensemble_fraction_overturned"] = optional_json(b.fraction_overturned);
        }
        if (!b.stiffness.empty()) {
            jb["stiffness"] = json_list(b.stiffness);
            jb["stiffness_sensitive"] = b.stiffness_sensitive;
        }
        bodies.push_back(std::move(jb));
    }
    j["bodies"] = std::move(bodies);
    return j;
}

}  // namespace blockdem
