#include "interrupt_guard.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iterator>

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace vrs_tool {

namespace {

constexpr int kForwarded[] = {SIGINT, SIGTERM, SIGHUP};
volatile std::sig_atomic_t g_signal = 0;

void note_signal(int sig) {
  g_signal = sig;
}

// Signals ignored when the run began (a background job's SIGINT) stay ignored, as shells expect.
void catch_signals(struct sigaction old[]) {
  struct sigaction sa = {};
  sa.sa_handler = note_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0; // no SA_RESTART: waitpid returns with EINTR, and the signal is passed on
  for (size_t i = 0; i < std::size(kForwarded); ++i) {
    sigaction(kForwarded[i], nullptr, &old[i]);
    if (old[i].sa_handler != SIG_IGN) sigaction(kForwarded[i], &sa, nullptr);
  }
}

void restore_signals(const struct sigaction old[]) {
  for (size_t i = 0; i < std::size(kForwarded); ++i)
    sigaction(kForwarded[i], &old[i], nullptr);
}

} // namespace

int run_guarded(const std::function<int()>& job, const std::function<void(pid_t, int)>& cleanup) {
  std::fflush(nullptr);
  struct sigaction old[std::size(kForwarded)];
  catch_signals(old); // before the fork: a signal in between would end this process unguarded
  // The child's own children (tile workers) become ours if it dies: waited for below, so that
  // nothing writes into what the cleanup removes.
  prctl(PR_SET_CHILD_SUBREAPER, 1);
  const pid_t child = fork();
  if (child < 0) {
    restore_signals(old);
    return job(); // no process to spare: run unguarded rather than not at all
  }
  if (child == 0) {
    restore_signals(old);
    int code = 1;
    try {
      code = job();
    } catch (...) {
    }
    std::fflush(nullptr);
    _exit(code);
  }
  int status = 0, forwarded = 0;
  while (waitpid(child, &status, 0) != child) {
    if (errno != EINTR) { // cannot happen to a child of ours; if it did, it is a failure
      restore_signals(old);
      cleanup(child, 0);
      return 1;
    }
    if (g_signal && g_signal != forwarded) kill(child, forwarded = g_signal);
  }
  if (WIFEXITED(status)) {
    restore_signals(old);
    return WEXITSTATUS(status);
  }
  const int sig = WTERMSIG(status);
  while (waitpid(-1, nullptr, 0) > 0 || errno == EINTR) {
  }
  restore_signals(old);
  cleanup(child, sig);
  std::signal(sig, SIG_DFL);
  raise(sig);
  return 128 + sig; // a signal whose default is not to end the process
}

} // namespace vrs_tool
