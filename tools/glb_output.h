// The command line's .glb output: levels of detail from one nested run (vrs/lods.h), written
// with every attribute the input has as one streamable binary glTF (vrs/glb.h).
#pragma once

#include <string>
#include <vector>

#include "vrs/simplify.h"

namespace vrs_tool {

struct GlbRequest {
  std::string input, output;
  std::vector<double> ratios; // the levels, finest first after sorting; {target} without --lods
  vrs::Options options;       // its target is ignored
  bool error_bound = false;   // record each level's certified bound (in the mesh's extras)
  bool compress = false;      // EXT_meshopt_compression
  bool progressive = false;   // one level (ratios[0], the base) and its insertion records
  bool json = false;
};

// "--lods 0.5,0.1,0.01" or "--lods N" (1, 1/2, 1/4, ... N levels): false on a bad list.
bool parse_lods(const std::string& text, std::vector<double>& ratios);

// Loads, simplifies, writes and reports; the process's exit status.
int run_glb(const GlbRequest& request);

} // namespace vrs_tool
