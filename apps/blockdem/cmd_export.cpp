// `blockdem export RUN_DIR --dxf FILE [--time T]`: the blocks of a finished run at one of its
// saved times (a VTK frame or a state file) as a DXF drawing, so that the deformed model goes
// back into CAD (docs/drawings.md). No physics here: io/run_frames and io/dxf_writer do the work.
#include <optional>
#include <set>

#include <fmt/format.h>

#include "apps/blockdem/commands.hpp"
#include "apps/blockdem/option_checks.hpp"
#include "io/dxf_writer.hpp"
#include "io/run_frames.hpp"

namespace blockdem::cli {
namespace {

struct ExportOptions {
    std::string run_dir;
    std::string dxf;
    std::optional<double> time_s;
};

void run_export(const ExportOptions& o) {
    const std::vector<RunFrame> frames = run_frames(o.run_dir);
    const RunFrame& frame = nearest_frame(frames, o.time_s);
    const std::vector<LayerPolygon> blocks = frame_blocks(o.run_dir, frame);
    write_dxf(o.dxf, blocks);
    std::set<std::string> layers;
    for (const LayerPolygon& b : blocks) layers.insert(dxf_layer_name(b.layer));
    fmt::print("wrote {}: {} blocks on {} layer{} ({}), in m, at t = {:g} s from {}\n", o.dxf, blocks.size(), layers.size(),
               layers.size() == 1 ? "" : "s", fmt::join(layers, ", "), frame.time_s, frame.file.string());
}

}  // namespace

void add_export_command(CLI::App& app) {
    auto options = std::make_shared<ExportOptions>();
    CLI::App* cmd = app.add_subcommand("export", "write the blocks of a run at a saved time as a CAD drawing");
    cmd->add_option("run_dir", options->run_dir, "the run's output folder")->required()->check(CLI::ExistingDirectory);
    cmd->add_option("--dxf", options->dxf, "the DXF drawing to write (closed polylines on layers named after each "
                                           "body's assembly or kind, in m)")
        ->required()
        ->check(output_file());
    cmd->add_option("--time", options->time_s, "the saved time nearest this [s] (a VTK frame or a state file); default: "
                                               "the last")
        ->check(finite_non_negative());
    cmd->callback([options] { run_export(*options); });
}

}  // namespace blockdem::cli
