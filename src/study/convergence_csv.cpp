#include "study/convergence_csv.hpp"

#include <fstream>

#include <fmt/format.h>

#include "io/input_error.hpp"

namespace blockdem {
namespace {

constexpr const char* header =
    "body,body_verdict,quantity,judged,dt,dt_2,dt_4,change_dt_to_dt_2,change_dt_2_to_dt_4,change_ratio,converged,"
    "kn_x0.5,kn_x1,kn_x2,stiffness_max_change,stiffness_sensitive,"
    "ensemble_mean,ensemble_min,ensemble_max,ensemble_relative_spread,ensemble_values_seen,ensemble_chaotic";

std::string cell(const std::optional<double>& v) { return v ? fmt::format("{:.9g}", *v) : std::string(); }
std::string cell(const std::optional<std::string>& v) { return v.value_or(""); }
std::string flag(bool b) { return b ? "1" : "0"; }

template <class T>
std::string at(const std::vector<std::optional<T>>& v, std::size_t i) {
    return i < v.size() ? cell(v[i]) : std::string();
}

std::string run_cells(const QuantityComparison& q) {
    std::vector<std::string> cells;
    for (std::size_t i = 0; i < 3; ++i) cells.push_back(q.discrete ? at(q.words, i) : at(q.values, i));
    cells.push_back(at(q.changes, 0));
    cells.push_back(at(q.changes, 1));
    cells.push_back(cell(q.change_ratio));
    cells.push_back(q.judged ? flag(q.converged) : "");
    return fmt::format("{}", fmt::join(cells, ","));
}

std::string stiffness_cells(const BodyConvergence& b, const std::string& quantity) {
    for (const StiffnessComparison& s : b.stiffness) {
        if (s.quantity != quantity) continue;
        std::vector<std::string> cells;
        for (std::size_t i = 0; i < 3; ++i) cells.push_back(s.discrete ? at(s.words, i) : at(s.values, i));
        cells.push_back(cell(s.max_change));
        cells.push_back(flag(s.sensitive));
        return fmt::format("{}", fmt::join(cells, ","));
    }
    return ",,,,";
}

std::string ensemble_cells(const BodyConvergence& b, const std::string& quantity) {
    for (const EnsembleSpread& s : b.ensemble) {
        if (s.quantity != quantity) continue;
        return fmt::format("{},{},{},{},{},{}", cell(s.mean), cell(s.min), cell(s.max), cell(s.relative_spread),
                           fmt::join(s.distinct, " "), flag(s.chaotic));
    }
    return ",,,,,";
}

}  // namespace

void write_convergence_csv(const std::filesystem::path& file, const ConvergenceResult& result) {
    std::ofstream out(file);
    if (!out) throw InputError({file.string(), "", 0, 0}, "cannot write the file");
    out << header << '\n';
    for (const BodyConvergence& b : result.bodies)
        for (const QuantityComparison& q : b.dt)
            out << fmt::format("{},{},{},{},{},{},{}\n", b.name, to_string(b.verdict), q.quantity, flag(q.judged), run_cells(q),
                               stiffness_cells(b, q.quantity), ensemble_cells(b, q.quantity));
}

}  // namespace blockdem
