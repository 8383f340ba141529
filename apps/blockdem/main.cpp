// blockdem: command-line front end. No physics here: it parses arguments, calls the library,
// and turns errors into a message and a non-zero exit status.
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "apps/blockdem/commands.hpp"
#include "io/input_error.hpp"
#include "world/simulation_error.hpp"

int main(int argc, char** argv) {
    CLI::App app{"blockdem: distinct element method for rigid blocks under earthquake shaking"};
    app.require_subcommand(1);
    blockdem::cli::add_run_command(app);
    blockdem::cli::add_check_command(app);
    blockdem::cli::add_motion_command(app);
    blockdem::cli::add_report_command(app);
    blockdem::cli::add_bench_command(app);
    blockdem::cli::add_sweep_command(app);
    blockdem::cli::add_converge_command(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const blockdem::InputError& e) {
        std::cerr << "error: " << e.what() << '\n';
        return 2;
    } catch (const blockdem::SimulationError& e) {
        std::cerr << "error: " << e.what() << '\n';
        return 3;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
