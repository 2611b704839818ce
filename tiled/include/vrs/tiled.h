// Tiled, out-of-core simplification (after Cignoni et al. 2003, "External memory management and
// simplification of huge meshes", and Isenburg et al. 2003, "Large mesh simplification using
// processing sequences"). The input is streamed once into a work directory and cut into spatial
// tiles; each tile is simplified by the core on its own, with the vertices it shares with
// other tiles (and their neighbours) locked; further levels over shifted or larger tiles
// release the previous borders until the target is met; the output is joined by input vertex
// id, which needs no welding: every output vertex is an input vertex.
//
// Each step is a function of the work directory alone, so tiles can run anywhere that sees it
// (local processes, Dask workers): begin -> { run_tile for every tile; next_level } -> finish.
// Errors are thrown as std::runtime_error with a message for the user.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace vrs::tiled {

struct Settings {
  double ratio = 0.5;                // of the input's faces
  uint64_t faces_per_tile = 2000000; // largest tile (faces_for_memory of the budget)
  std::string workdir;               // made if missing; must be writable
  // Vertices written twice at one position along a seam (vrs::SplitVertices): "seam", "weld"
  // or "keep"; "" chooses as the CLI does in core: weld when the vertices hold nothing but a
  // position and no face holds per-corner data, else seam.
  std::string split_vertices;
};

struct Level {
  int level = 0;       // 1, 2, ...
  uint64_t tiles = 0;  // tiles to run at this level; 0 once the run is done
  uint64_t faces = 0;  // faces entering the level
  uint64_t target = 0; // faces wanted in the end
  double ratio = 1.0;  // what each tile keeps at this level
  // Tiles of up to the whole budget (a level after one that stalled): run one at a time.
  bool serial = false;
};

// "" when a tiled run can write `output` from `input`, else why not: a tiled run writes the
// input's own format (.ply, .obj, .off), every vertex copied as the input holds it (every
// property, in its own precision) and every corner's data kept. Asked before any work.
std::string output_refusal(const std::string& input, const std::string& output);

// Streams `input` (.ply ascii or binary, .obj, ascii .off) into the work directory and cuts
// level 1. What it cannot carry to the output (a PLY face property of more than 4 bytes, an
// element other than vertex and face, OFF face colors) is refused here, with its name.
Level begin(const std::string& input, const Settings& settings);
// Simplifies one tile of the work directory's current level; reads and writes its files only,
// and writes its output atomically (a re-run after a killed worker is safe). Tiles that run side
// by side use one thread each; a level of one tile runs alone, on `lone_threads` (0: every
// core). The output is the same either way.
void run_tile(const std::string& workdir, int level, uint64_t tile, int lone_threads = 0);
// Once every tile of the current level has run: cuts the next level, or returns tiles == 0.
Level next_level(const std::string& workdir);
// Writes the output atomically in the input's format (see output_refusal): the input's
// vertices that faces still use, in input order and as the input holds them, and the faces
// with their per-corner data. Returns the output's face count.
uint64_t finish(const std::string& workdir, const std::string& output);
// The temporary name process `pid` writes `path` under until it is whole (then renamed): what
// to remove when that process was killed.
std::string unfinished_name(const std::string& path, long pid);

// Makes a fresh work directory inside `parent` (made if missing; "" = the current one), named
// vrsimplify-tiles-XXXXXX, and returns its path: a run never writes into, nor removes, a folder
// the user named.
std::string make_work_dir(const std::string& parent);
// Removes the work directory and everything in it.
void discard(const std::string& workdir);

// Faces a tile may hold for a memory budget of `bytes`: a quarter of it, so that up to
// kTilesInMemory tiles run at once within it. The tiles, and so the output, depend on the
// budget only, never on how many workers run them. And whether a mesh of `faces` is better
// run in core within `bytes`.
constexpr int kTilesInMemory = 4;
uint64_t faces_for_memory(uint64_t bytes);
bool fits_in_core(uint64_t faces, uint64_t bytes);
// "2G", "512M", "1.5G", "800000K" -> bytes; 0 when unreadable.
uint64_t parse_memory(const std::string& text);

// Reads the mesh file through the streaming reader, keeping nothing: "" when it is well formed,
// else what is wrong and where (as begin() would say). In constant memory, whatever the file
// claims: the in-core readers' check before they allocate what a header declares.
std::string check_mesh_file(const std::string& path);

// Runs every tile of `level` on `workers` local processes (fork; at most kTilesInMemory): the
// embedded default. When a signal interrupts the wait, `interrupted` (if any) is called: if it
// throws, the workers are killed and reaped, then the exception goes on (Python's Ctrl-C).
void run_level_locally(const std::string& workdir, const Level& level, int workers, bool progress,
                       const std::function<void()>& interrupted = {});

} // namespace vrs::tiled
