// The embedded default: a level's tiles on local worker processes, each taking every
// workers-th tile, so that each holds one tile at a time and a tile's memory is returned to the
// system when its process ends.
#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include "vrs/tiled.h"

namespace vrs::tiled {

void run_level_locally(const std::string& workdir, const Level& level, int workers, bool progress) {
  const int cores = std::max(workers, 1); // a lone tile's threads
  workers = int(std::max<uint64_t>(1, std::min<uint64_t>({uint64_t(std::max(workers, 1)),
                                                          uint64_t(kTilesInMemory), level.tiles})));
  if (progress)
    std::fprintf(stderr, "level %d: %llu faces in %llu tiles on %d processes, keeping %.3g\n",
                 level.level, (unsigned long long)level.faces, (unsigned long long)level.tiles,
                 workers, level.ratio);
  std::fflush(nullptr);
  std::vector<pid_t> children;
  for (int w = 0; w < workers; ++w) {
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("cannot start a worker process");
    if (pid == 0) {
      int status = 0;
      try {
        for (uint64_t t = uint64_t(w); t < level.tiles; t += uint64_t(workers))
          run_tile(workdir, level.level, t, cores);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "vrsimplify: %s\n", e.what());
        status = 1;
      }
      std::fflush(nullptr);
      _exit(status);
    }
    children.push_back(pid);
  }
  bool failed = false;
  for (pid_t pid : children) {
    int status = 0;
    if (waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
      failed = true;
  }
  if (failed) throw std::runtime_error("a tile worker failed (its message is above)");
}

} // namespace vrs::tiled
