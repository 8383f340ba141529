#pragma once
// SIGINT (Ctrl-C) and SIGTERM ask a run or a sweep to stop cleanly: the handler only sets a
// flag (the one piece of global state the project allows, since a handler can reach nothing
// else), which the run loop reads between steps. A second signal ends the process at once.
#include <atomic>

namespace blockdem::cli {

/// Installs the handlers; returns the flag they set.
const std::atomic<bool>& install_stop_handlers();

/// The exit status for the signal that set the flag: 130 (SIGINT), 143 (SIGTERM), 0 if none.
int stop_exit_status();

}  // namespace blockdem::cli
