// blockdem: command-line front end. No physics here: it parses arguments, calls the library,
// and turns errors into a message and an exit status (docs/outputs.md):
//   0 ok; 1 internal error (a bug, or a broken installation); 2 bad input (scenario, arguments,
//   an output folder that holds another run, a run that would not fit the machine); 3 a run
//   that failed after it started (unstable, an assembly that did not settle); 4 an output file
//   could not be written (disk full, file too large, permissions); 130 / 143 interrupted by
//   SIGINT / SIGTERM (results so far kept).
#include <csignal>
#include <exception>
#include <iostream>
#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>

#include "apps/blockdem/commands.hpp"
#include "io/input_error.hpp"
#include "io/output_file.hpp"
#include "world/simulation_error.hpp"

namespace {

// "blockdem 0.1.0 (commit 6792f38fa5e0)": the version of CMake's project(), and the commit the
// build was configured at (CMakeLists.txt; absent outside a git checkout).
std::string version_text() {
    const std::string commit = BLOCKDEM_GIT_COMMIT;
    return std::string("blockdem ") + BLOCKDEM_VERSION + (commit.empty() ? "" : " (commit " + commit + ")");
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"blockdem: distinct element method for rigid blocks under earthquake shaking"};
    app.set_version_flag("--version", version_text(), "print the version and the commit, then exit");
    app.require_subcommand(1);
    blockdem::cli::add_run_command(app);
    blockdem::cli::add_check_command(app);
    blockdem::cli::add_motion_command(app);
    blockdem::cli::add_report_command(app);
    blockdem::cli::add_bench_command(app);
    blockdem::cli::add_sweep_command(app);
    blockdem::cli::add_converge_command(app);
    blockdem::cli::add_calibrate_command(app);
    blockdem::cli::add_export_command(app);
    blockdem::cli::add_limit_command(app);
    // With a file-size limit (ulimit -f) the kernel would kill the process with SIGXFSZ and no
    // message; ignored, the write fails with EFBIG and the run says which file.
    std::signal(SIGXFSZ, SIG_IGN);
    // An unknown first word: CLI11 said only "A subcommand is required".
    if (argc > 1 && argv[1][0] != '-') {
        std::string names;
        bool known = false;
        for (const CLI::App* command : app.get_subcommands({})) {
            known = known || command->get_name() == argv[1];
            names += (names.empty() ? "" : ", ") + command->get_name();
        }
        if (!known) {
            std::cerr << "error: '" << argv[1] << "' is not a blockdem command; the commands are " << names
                      << " (blockdem --help)\n";
            return 2;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e);  // --help
    } catch (const CLI::ParseError& e) {
        app.exit(e);  // prints the message and the usage
        return 2;
    } catch (const blockdem::cli::ExitStatus& e) {
        return e.code;
    } catch (const blockdem::InputError& e) {
        std::cerr << "error: " << e.what() << '\n';
        return 2;
    } catch (const blockdem::SimulationError& e) {
        std::cerr << "error: " << e.what() << '\n';
        return 3;
    } catch (const blockdem::OutputError& e) {
        std::cerr << "error: could not write the output: " << e.what() << '\n';
        return 4;
    } catch (const std::invalid_argument& e) {
        std::cerr << "error: " << e.what() << '\n';  // a bad value the library refused (sweep plans)
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
