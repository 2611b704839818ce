// The CLI's tiled path (--memory, --scheduler): a mesh larger than the memory budget is
// simplified in tiles on local worker processes, or handed to the Python package's Dask driver.
#pragma once

#include <cstdint>
#include <string>

namespace vrs_tool {

struct TiledRequest {
  std::string input, output, workdir, scheduler;
  double ratio = 0.5;
  uint64_t memory = 0; // bytes
  int workers = 0;     // 0: the machine's cores
  bool progress = false, json = false, keep_workdir = false;
  std::string split_vertices; // seam, weld, keep; "": chosen from the file's data
};

// Faces the file holds (PLY: its header; other formats: estimated from the size), 0 if unknown.
uint64_t estimate_faces(const std::string& path);
// Exit code as the CLI's.
int run_tiled(const TiledRequest& request);

} // namespace vrs_tool
