// The embedded default: a level's tiles on local worker processes, each taking the next tile
// not yet taken, largest first (a counter in memory the processes share), so that tiles of
// unequal sizes keep every process busy to the end; each holds one tile at a time, and a
// tile's memory is returned to the system when its process ends.
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <memory>
#include <new>
#include <numeric>
#include <stdexcept>
#include <vector>

#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "tile_files.h"
#include "vrs/simplify.h"
#include "vrs/tiled.h"

namespace vrs::tiled {

void run_level_locally(const std::string& workdir, const Level& level, int workers, bool progress,
                       const std::function<void()>& interrupted) {
  // 0: the machine's cores, as documented (and as the CLI counts them).
  if (workers <= 0) workers = vrs::usable_cores();
  const int cores = workers;     // a lone tile's threads
  if (level.serial) workers = 1; // tiles of the whole budget: one at a time
  workers = int(std::max<uint64_t>(1, std::min<uint64_t>({uint64_t(std::max(workers, 1)),
                                                          uint64_t(kTilesInMemory), level.tiles})));
  if (progress)
    std::fprintf(stderr, "level %d: %llu faces in %llu tiles on %d processes, keeping %.3g\n",
                 level.level, (unsigned long long)level.faces, (unsigned long long)level.tiles,
                 workers, level.ratio);
  std::vector<uint64_t> order(level.tiles), size(level.tiles);
  for (uint64_t t = 0; t < level.tiles; ++t)
    size[t] = record_count(tile_path(workdir, level.level, t, ".in"), false); // the order only
  std::iota(order.begin(), order.end(), uint64_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](uint64_t a, uint64_t b) { return size[a] > size[b]; });
  std::fflush(nullptr);
  void* shared = mmap(nullptr, sizeof(std::atomic<uint64_t>), PROT_READ | PROT_WRITE,
                      MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (shared == MAP_FAILED) throw std::runtime_error("cannot share memory with the workers");
  const std::unique_ptr<void, void (*)(void*)> unmap(
      shared, [](void* p) { munmap(p, sizeof(std::atomic<uint64_t>)); });
  auto* next = new (shared) std::atomic<uint64_t>(0);
  static_assert(std::atomic<uint64_t>::is_always_lock_free, "shared between processes");
  const pid_t driver = getpid();
  std::vector<pid_t> children;
  bool failed = false;
  for (int w = 0; w < workers && !failed; ++w) {
    const pid_t pid = fork();
    if (pid < 0) {
      std::fprintf(stderr, "vrsimplify: cannot start a worker process\n");
      failed = true;
      next->store(level.tiles); // the others stop after their tile
      break;
    }
    if (pid == 0) {
      // Killed with the driver, not left writing into a work directory being removed; and by
      // Ctrl-C, whatever handler the driver (Python) has for it.
      prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (getppid() != driver) _exit(1);
      for (int sig : {SIGINT, SIGTERM, SIGHUP})
        std::signal(sig, SIG_DFL);
      int status = 0;
      try {
        for (uint64_t i = next->fetch_add(1); i < level.tiles; i = next->fetch_add(1))
          run_tile(workdir, level.level, order[i], cores);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "vrsimplify: %s\n", e.what());
        status = 1;
      }
      std::fflush(nullptr);
      _exit(status);
    }
    children.push_back(pid);
  }
  for (size_t c = 0; c < children.size(); ++c) {
    int status = 0;
    while (waitpid(children[c], &status, 0) < 0 && errno == EINTR) {
      // A signal: the caller decides whether the run goes on. If not, no worker outlives it.
      try {
        if (interrupted) interrupted();
      } catch (...) {
        for (size_t k = c; k < children.size(); ++k)
          kill(children[k], SIGKILL);
        for (size_t k = c; k < children.size(); ++k)
          while (waitpid(children[k], nullptr, 0) < 0 && errno == EINTR) {
          }
        throw;
      }
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) failed = true;
  }
  if (failed) throw std::runtime_error("a tile worker failed (its message is above)");
}

} // namespace vrs::tiled
