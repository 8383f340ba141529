#include "apps/blockdem/stop_signal.hpp"

#include <csignal>

namespace blockdem::cli {
namespace {

std::atomic<bool> stop_requested{false};
std::atomic<int> stop_signal{0};

extern "C" void on_stop_signal(int signal_number) {
    stop_signal.store(signal_number);
    stop_requested.store(true);
    std::signal(SIGINT, SIG_DFL);  // a second Ctrl-C ends the process at once
    std::signal(SIGTERM, SIG_DFL);
}

}  // namespace

const std::atomic<bool>& install_stop_handlers() {
    std::signal(SIGINT, on_stop_signal);
    std::signal(SIGTERM, on_stop_signal);
    return stop_requested;
}

int stop_exit_status() {
    if (!stop_requested.load()) return 0;
    return 128 + stop_signal.load();
}

}  // namespace blockdem::cli
