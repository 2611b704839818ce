#pragma once
// A long run that must not leave its temporaries behind, however it ends.
#include <functional>

#include <sys/types.h>

namespace vrs_tool {

// Runs `job` in a child process and waits for it. If the child dies of a signal (Ctrl-C, kill,
// a closed terminal, the kernel's out-of-memory killer), `cleanup(child, signal)` runs here after
// it, in plain code rather than in a signal handler, then this process dies of the same signal.
// SIGINT, SIGTERM and SIGHUP sent to this process alone are passed on to the child. Returns the
// child's exit status otherwise.
int run_guarded(const std::function<int()>& job,
                const std::function<void(pid_t child, int signal)>& cleanup);

} // namespace vrs_tool
