// `blockdem motion FILE`: the facts of a ground-motion record, its drift with and without
// baseline correction, its elastic response spectrum (CSV) and a figure (tools/plot_motion.py,
// run with Debian's /usr/bin/python3; the figure is optional, the CSV files are not).
// No physics here: everything is computed by the library.
#include <cstdlib>
#include <sys/wait.h>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "apps/blockdem/commands.hpp"
#include "apps/blockdem/option_checks.hpp"
#include "io/input_error.hpp"
#include "motion/intensity_measures.hpp"
#include "motion/record_processing.hpp"
#include "motion/records/acceleration_units.hpp"
#include "motion/records/ground_motion_record.hpp"
#include "motion/response_spectrum.hpp"

namespace blockdem::cli {
namespace {

namespace fs = std::filesystem;

struct MotionOptions {
    std::string file;
    std::string format = "auto";
    std::string units;
    double dt_s = 0.0;
    std::string component;
    std::string out = ".";
    double damping = 0.05;
    std::vector<double> periods_s;
    std::string method = "exact";
    std::string baseline = "polynomial";
    int baseline_order = 3;
    bool plot = true;
    std::string plot_script;
};

void print_facts(const GroundMotionRecord& r, const IntensityMeasures& m) {
    const double g = standard_gravity_m_s2;
    fmt::print("record      {} ({})\n", r.file, record_format_name(r.format));
    fmt::print("event       {}\n", r.event.empty() ? "(not in the file)" : r.event);
    fmt::print("station     {}\n", r.station.empty() ? "(not in the file)" : r.station);
    fmt::print("component   {}\n", r.component.empty() ? "(not in the file)" : r.component);
    fmt::print("units       {} (x {:.9g} to m/s^2; g = {} m/s^2)\n", r.units_in_file, r.to_m_s2, g);
    fmt::print("dt          {:g} s\n", r.dt_s);
    fmt::print("points      {}\n", r.npts());
    fmt::print("duration    {:.4f} s\n", r.duration_s());
    fmt::print("PGA         {:.6g} m/s^2 ({:.4f} g) at {:.4f} s\n", m.pga_signed_m_s2, m.pga_m_s2 / g, m.pga_time_s);
    fmt::print("PGV         {:.6g} m/s at {:.4f} s\n", m.pgv_m_s, m.pgv_time_s);
    fmt::print("PGD         {:.6g} m at {:.4f} s\n", m.pgd_m, m.pgd_time_s);
    fmt::print("Arias       {:.6g} m/s\n", m.arias_m_s);
    fmt::print("D5-95       {:.4f} s (t5 = {:.4f} s, t95 = {:.4f} s); D5-75 {:.4f} s\n", m.d5_95_s, m.t5_s, m.t95_s, m.d5_75_s);
    for (const auto& note : r.notes) fmt::print("note        {}\n", note);
}

void print_drift(const IntensityMeasures& raw, const IntensityMeasures& corrected, const BaselineCorrection& c) {
    fmt::print("drift       as recorded:               final velocity {:+.6g} m/s, final displacement {:+.6g} m\n",
               raw.final_velocity_m_s, raw.final_displacement_m);
    fmt::print("            baseline {:<13} {}: final velocity {:+.6g} m/s, final displacement {:+.6g} m (PGA {:.6g} m/s^2)\n",
               baseline_method_name(c.method), c.method == BaselineMethod::polynomial || c.method == BaselineMethod::displacement_polynomial
                   ? fmt::format("order {}", c.order) : std::string("       "),
               corrected.final_velocity_m_s, corrected.final_displacement_m, corrected.pga_m_s2);
}

void write_record_csv(const fs::path& path, const GroundMotionRecord& r, const std::vector<double>& corrected) {
    const auto raw = integrate_record(r.acceleration_m_s2, r.dt_s);
    const auto fixed = integrate_record(corrected, r.dt_s);
    std::ofstream out(path);
    out << "time_s,acceleration_m_s2,velocity_m_s,displacement_m,corrected_acceleration_m_s2,corrected_velocity_m_s,"
           "corrected_displacement_m\n";
    for (std::size_t k = 0; k < r.npts(); ++k)
        fmt::print(out, "{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", static_cast<double>(k) * r.dt_s,
                   r.acceleration_m_s2[k], raw.velocity_m_s[k], raw.displacement_m[k], corrected[k], fixed.velocity_m_s[k],
                   fixed.displacement_m[k]);
    if (!out) throw std::runtime_error(fmt::format("cannot write {}", path.string()));
}

void write_spectrum_csv(const fs::path& path, const std::vector<SpectrumOrdinate>& spectrum, double damping) {
    std::ofstream out(path);
    fmt::print(out, "# elastic response spectrum, damping ratio {:g}\n", damping);
    out << "period_s,sd_m,psv_m_s,psa_m_s2,psa_g\n";
    for (const auto& s : spectrum)
        fmt::print(out, "{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", s.period_s, s.sd_m, s.psv_m_s, s.psa_m_s2,
                   s.psa_m_s2 / standard_gravity_m_s2);
    if (!out) throw std::runtime_error(fmt::format("cannot write {}", path.string()));
}

// tools/plot_motion.py beside the source tree: found from the executable (build/ is in the tree).
fs::path find_plot_script(const std::string& given) {
    if (!given.empty()) return given;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    std::vector<fs::path> candidates{fs::current_path() / "tools" / "plot_motion.py"};
    if (!ec)
        for (fs::path dir = exe.parent_path(); !dir.empty() && dir != dir.parent_path(); dir = dir.parent_path())
            candidates.push_back(dir / "tools" / "plot_motion.py");
    for (const auto& c : candidates)
        if (fs::is_regular_file(c)) return c;
    return {};
}

std::string quoted(const fs::path& p) {
    std::string out = "'";
    for (char c : p.string()) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

constexpr int missing_matplotlib = 3;  // plot_motion.py's exit status when it cannot import matplotlib

void plot(const MotionOptions& o, const fs::path& out_dir) {
    const fs::path python = "/usr/bin/python3";
    const fs::path script = find_plot_script(o.plot_script);
    if (!fs::exists(python) || script.empty()) {
        fmt::print("plot        skipped: {} not found\n", script.empty() ? "tools/plot_motion.py" : python.string());
        return;
    }
    const std::string command = fmt::format("{} {} {}", quoted(python), quoted(script), quoted(out_dir));
    const int status = std::system(command.c_str());
    const int exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (exit_code == 0)
        fmt::print("plot        {}\n", (out_dir / "motion.png").string());
    else if (exit_code == missing_matplotlib)
        fmt::print("plot        skipped: matplotlib is missing (apt-get install python3-matplotlib python3-numpy)\n");
    else
        fmt::print("plot        skipped: {} failed (exit status {})\n", script.string(), exit_code);
}

// Refused before the record is read: a period outside the range would never finish.
void check_options(const MotionOptions& o) {
    for (double period : o.periods_s) {
        try {
            checked_spectrum_period(period);
        } catch (const std::invalid_argument& e) {
            throw InputError({"", "--periods", 0, 0}, e.what());
        }
    }
    if (o.dt_s != 0.0 && !(o.dt_s >= min_record_dt_s && o.dt_s <= max_record_dt_s))
        throw InputError({"", "--dt", 0, 0}, fmt::format("{:g} s is outside the accepted {:g} s to {:g} s", o.dt_s,
                                                        min_record_dt_s, max_record_dt_s));
    const int lowest = o.baseline == "displacement_polynomial" ? 3 : 2;
    if (o.baseline_order < lowest || o.baseline_order > 6)
        throw InputError({"", "--baseline-order", 0, 0}, fmt::format("{} is outside {} to 6", o.baseline_order, lowest));
}

RecordReadOptions read_options(const MotionOptions& o) {
    RecordReadOptions r;
    try {
        r.format = parse_record_format(o.format);
    } catch (const std::invalid_argument& e) {
        throw InputError({"", "--format", 0, 0}, e.what());
    }
    r.units = o.units;
    r.dt_s = o.dt_s;
    r.component = o.component;
    return r;
}

void run_motion(const MotionOptions& o) {
    check_options(o);
    const GroundMotionRecord record = read_ground_motion_record(o.file, read_options(o));
    const IntensityMeasures measures = intensity_measures(record.acceleration_m_s2, record.dt_s);
    print_facts(record, measures);
    BaselineCorrection correction{parse_baseline_method(o.baseline), o.baseline_order};
    const std::vector<double> corrected = correct_baseline(record.acceleration_m_s2, record.dt_s, correction);
    print_drift(measures, intensity_measures(corrected, record.dt_s), correction);
    SpectrumOptions spectrum_options{o.damping, o.periods_s, parse_spectrum_method(o.method)};
    const auto spectrum = response_spectrum(record.acceleration_m_s2, record.dt_s, spectrum_options);
    const fs::path out_dir = o.out;
    fs::create_directories(out_dir);
    write_record_csv(out_dir / "record.csv", record, corrected);
    write_spectrum_csv(out_dir / "spectrum.csv", spectrum, o.damping);
    fmt::print("spectrum    {} ({} periods, damping {:g}, {} integration)\n", (out_dir / "spectrum.csv").string(),
               spectrum.size(), o.damping, o.method);
    fmt::print("series      {}\n", (out_dir / "record.csv").string());
    if (o.plot) plot(o, out_dir);
}

}  // namespace

void add_motion_command(CLI::App& app) {
    auto options = std::make_shared<MotionOptions>();
    auto* cmd = app.add_subcommand("motion", "Facts, drift and response spectrum of a ground-motion record");
    cmd->add_option("file", options->file, "record file (PEER AT2, K-NET/KiK-net, COSMOS V2, JMA CSV, plain text)")
        ->required()->check(CLI::ExistingFile);
    cmd->add_option("--format", options->format, "auto, peer-at2, knet, cosmos-v2, jma-csv, plain")->capture_default_str();
    cmd->add_option("--units", options->units, "override the file's units: m/s^2, gal, g (g = 9.80665 m/s^2)");
    cmd->add_option("--dt", options->dt_s, "[s] sample interval of a values-only text file")->check(finite_positive());
    cmd->add_option("--component", options->component, "column or channel to read (e.g. NS, EW, UD)");
    cmd->add_option("--out", options->out, "folder for spectrum.csv, record.csv and motion.png")
        ->capture_default_str()
        ->check(output_folder());
    cmd->add_option("--damping", options->damping, "damping ratio of the spectrum")->capture_default_str()->check(finite_in(0.0, 0.99));
    cmd->add_option("--periods", options->periods_s,
                    fmt::format("[s] periods of the spectrum (default 100 from 0.01 to 10 s; each 0 (the PGA) or {:g} to {:g} s)",
                                min_spectrum_period_s, max_spectrum_period_s));
    cmd->add_option("--method", options->method, "spectrum integration: exact (piecewise-linear) or newmark")
        ->capture_default_str()->check(CLI::IsMember({"exact", "newmark"}));
    cmd->add_option("--baseline", options->baseline, "correction for the drift report: " + baseline_method_names())
        ->capture_default_str()->check(CLI::IsMember({"none", "mean", "linear", "polynomial", "displacement_polynomial"}));
    cmd->add_option("--baseline-order", options->baseline_order, "polynomial order (2..6; 3..6 for displacement_polynomial)")
        ->capture_default_str();
    cmd->add_flag("!--no-plot", options->plot, "write the CSV files only");
    cmd->add_option("--plot-script", options->plot_script, "path of tools/plot_motion.py when it is not found");
    cmd->callback([options] { run_motion(*options); });
}

}  // namespace blockdem::cli
