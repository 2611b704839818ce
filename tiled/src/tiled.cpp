// The tiled run's steps, each a function of the work directory (see vrs/tiled.h).
#include "vrs/tiled.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include "mesh_stream.h"
#include "partition.h"
#include "tile_files.h"
#include "vrs/simplify.h"

namespace vrs::tiled {

namespace {

constexpr int kMaxLevels = 12;
constexpr double kSlack = 0.005; // done within half a per cent of the target
// The share of the whole budget (kTilesInMemory tiles) the last, single tile is left with:
// 0.5 measured best of 0.25, 0.5, 0.7 and 0.9 (max error at 1 % on two bunnies and a terrain).
constexpr double kLastRoom = 0.5;

std::string num(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

Box box_of(const State& s) {
  Box b;
  for (int a = 0; a < 3; ++a) {
    b.lo[a] = float(state_number(s, "lo" + std::to_string(a)));
    b.hi[a] = float(state_number(s, "hi" + std::to_string(a)));
  }
  return b;
}

// Level 1's faces: faces.bin with the positions of vertices.bin (held in memory meanwhile).
FaceSource input_faces(const std::string& dir, const std::vector<float>& positions) {
  return [&dir, &positions](const std::function<void(const FaceRecord&)>& fn) {
    std::FILE* f = std::fopen((dir + "/faces.bin").c_str(), "rb");
    if (!f) throw std::runtime_error("cannot read " + dir + "/faces.bin");
    std::vector<uint32_t> buf(3 * 8192);
    size_t n;
    FaceRecord r{};
    while ((n = std::fread(buf.data(), 12, buf.size() / 3, f)) > 0)
      for (size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
          r.v[c] = buf[3 * i + c];
          std::memcpy(r.p[c], &positions[3 * size_t(r.v[c])], 12);
        }
        fn(r);
      }
    std::fclose(f);
  };
}

FaceSource level_outputs(const std::string& dir, int level, uint64_t tiles) {
  return [dir, level, tiles](const std::function<void(const FaceRecord&)>& fn) {
    for (uint64_t t = 0; t < tiles; ++t)
      for_each_record(tile_path(dir, level, t, ".out"), fn);
  };
}

// What each tile of the level keeps (see run_tile).
double keep_of(const State& s) {
  const double ratio = state_number(s, "ratio");
  if (state_number(s, "tiles") == 1) return ratio;
  const double room = kLastRoom * double(kTilesInMemory) * state_number(s, "faces_per_tile");
  return std::max(ratio, std::min(1.0, room / state_number(s, "faces")));
}

Level level_of(const State& s) {
  Level l;
  l.level = int(state_number(s, "level"));
  l.tiles = s.count("done") ? 0 : uint64_t(state_number(s, "tiles"));
  l.faces = uint64_t(state_number(s, "faces"));
  l.target = uint64_t(state_number(s, "target"));
  l.ratio = s.count("done") ? state_number(s, "ratio") : keep_of(s);
  return l;
}

} // namespace

Level begin(const std::string& input, const Settings& settings) {
  if (!(settings.ratio >= 0 && settings.ratio <= 1))
    throw std::runtime_error("ratio must be in [0, 1], got " + num(settings.ratio));
  if (settings.faces_per_tile < 1000)
    throw std::runtime_error("tiles of fewer than 1000 faces: give more memory");
  const std::string& dir = settings.workdir;
  make_dir(dir);
  std::FILE* in = std::fopen(input.c_str(), "rb");
  if (!in) throw std::runtime_error("cannot read " + input + ": " + std::strerror(errno));
  std::setvbuf(in, nullptr, _IOFBF, 1 << 20);

  // The one streaming pass over the input.
  Box box{{HUGE_VALF, HUGE_VALF, HUGE_VALF}, {-HUGE_VALF, -HUGE_VALF, -HUGE_VALF}};
  uint64_t vertices = 0, faces = 0;
  int64_t max_index = -1, min_index = 0;
  {
    RecordWriter vout(dir + "/vertices.bin"), fout(dir + "/faces.bin");
    StreamSink sink;
    sink.vertex = [&](const float p[3]) {
      vout.write(p, 12);
      ++vertices;
      for (int a = 0; a < 3; ++a)
        if (std::isfinite(p[a]))
          box.lo[a] = std::min(box.lo[a], p[a]), box.hi[a] = std::max(box.hi[a], p[a]);
    };
    sink.triangle = [&](const int64_t v[3]) {
      uint32_t t[3];
      for (int c = 0; c < 3; ++c) {
        max_index = std::max(max_index, v[c]);
        min_index = std::min(min_index, v[c]);
        t[c] = uint32_t(std::min<int64_t>(std::max<int64_t>(v[c], 0), 0xffffffffLL));
      }
      fout.write(t, 12);
      ++faces;
    };
    const std::string error = read_mesh_stream(in, input, sink);
    std::fclose(in);
    if (!error.empty()) throw std::runtime_error("cannot read " + input + ": " + error);
    if (min_index < 0 || max_index >= int64_t(vertices))
      throw std::runtime_error("cannot read " + input + ": a face has vertex index " +
                               std::to_string(min_index < 0 ? min_index : max_index) +
                               ", out of range for " + std::to_string(vertices) + " vertices");
    if (vertices >= 0xfffffffeull)
      throw std::runtime_error("more than 4 294 967 293 vertices: not supported");
    vout.commit();
    fout.commit();
  }
  if (faces == 0) throw std::runtime_error(input + " has no faces");
  for (int a = 0; a < 3; ++a)
    if (!(box.lo[a] <= box.hi[a])) box.lo[a] = box.hi[a] = 0;

  State s;
  s["input"] = input;
  s["vertices"] = num(double(vertices));
  s["input_faces"] = num(double(faces));
  s["faces"] = num(double(faces));
  s["target"] = num(std::floor(settings.ratio * double(faces)));
  s["ratio"] = num(settings.ratio);
  s["faces_per_tile"] = num(double(settings.faces_per_tile));
  s["level"] = "1";
  s["stalls"] = "0";
  for (int a = 0; a < 3; ++a) {
    s["lo" + std::to_string(a)] = num(box.lo[a]);
    s["hi" + std::to_string(a)] = num(box.hi[a]);
  }
  {
    std::vector<float> positions(3 * vertices);
    std::FILE* f = std::fopen((dir + "/vertices.bin").c_str(), "rb");
    const size_t got = f ? std::fread(positions.data(), 12, vertices, f) : 0;
    if (f) std::fclose(f);
    if (got != vertices) throw std::runtime_error("cannot read back " + dir + "/vertices.bin");
    // A mesh that fits the whole budget is one tile at once (what the last level would be).
    const uint64_t budget =
        faces <= settings.faces_per_tile * kTilesInMemory ? faces : settings.faces_per_tile;
    s["tiles"] = num(double(partition(dir, 1, vertices, box, budget, input_faces(dir, positions))));
  }
  std::remove((dir + "/faces.bin").c_str()); // in the tiles now; the disk is the next level's
  write_state(dir, s);
  return level_of(s);
}

void run_tile(const std::string& dir, int level, uint64_t tile, int lone_threads) {
  const State s = read_state(dir);
  std::vector<FaceRecord> in;
  for_each_record(tile_path(dir, level, tile, ".in"),
                  [&](const FaceRecord& r) { in.push_back(r); });
  // Global ids -> local ones (sorted: the tile's mesh does not depend on the file's order).
  std::vector<uint32_t> ids;
  ids.reserve(3 * in.size());
  for (const FaceRecord& r : in)
    ids.insert(ids.end(), r.v, r.v + 3);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  auto local = [&](uint32_t v) {
    return uint32_t(std::lower_bound(ids.begin(), ids.end(), v) - ids.begin());
  };
  vrs::Mesh mesh;
  mesh.positions.resize(3 * ids.size());
  mesh.triangles.resize(3 * in.size());
  // Locked: every corner of a face at the border (one with a shared corner). A vertex that is
  // not shared has all its faces in this tile, so the tile sees every face that locks it.
  std::vector<uint8_t> locked(ids.size(), 0);
  for (size_t f = 0; f < in.size(); ++f)
    for (int c = 0; c < 3; ++c) {
      const uint32_t l = local(in[f].v[c]);
      mesh.triangles[3 * f + c] = l;
      std::memcpy(&mesh.positions[3 * size_t(l)], in[f].p[c], 12);
      if (in[f].shared) locked[l] = 1;
    }
  // On the first two levels the ratio applies to the faces the tile may change: asking the
  // faces along its locked border to go too makes the rest of the tile go further than the
  // target asks (measured: +21 % mean error at 10 % on 1.2 M faces); the next level, shifted,
  // releases them. From the third level on (small remainders, coarser tiles) a tile goes as
  // far as the level's ratio of all its faces, without the core's last resort, so that the
  // run converges. Tiles never go below what one tile of the last level can take (kLastRoom):
  // the last level, in core over the whole mesh, then spends the faces where the surface needs
  // them, not evenly per tile (1 % of a 2 M-face terrain in 222 tiles: max error 3.0 times the
  // in-core one's without, 0.99 times with).
  in = {};
  uint64_t bordering = 0; // faces with a locked corner
  for (size_t f = 0; f < mesh.face_count(); ++f)
    bordering += (locked[mesh.triangles[3 * f]] | locked[mesh.triangles[3 * f + 1]] |
                  locked[mesh.triangles[3 * f + 2]]) != 0;
  const bool alone = state_number(s, "tiles") == 1;
  const double keep = keep_of(s);
  vrs::Options opt;
  opt.target.kind = vrs::TargetKind::Faces;
  const double faces = double(mesh.face_count());
  opt.target.faces =
      level <= 2 ? size_t(double(bordering) + std::round(keep * (faces - double(bordering))))
                 : size_t(std::round(keep * faces));
  // One tile is the whole mesh, nothing locked: as in core, the last resort may reach the
  // target.
  opt.relax_to_reach_target = alone;
  // A tile's cut is a border of its piece but no border of the mesh: only the whole mesh (the
  // last level, in core) judges whether the border needs simplifying.
  opt.simplify_boundary_when_needed = alone;
  opt.threads = alone ? std::max(0, lone_threads) : 1;
  opt.locked = &locked;
  const vrs::Report rep = vrs::simplify(mesh, opt);
  if (!rep.ok) throw std::runtime_error("tile " + std::to_string(tile) + ": " + rep.message);
  std::vector<uint32_t> global(mesh.vertex_count());
  for (size_t v = 0; v < rep.remap.size(); ++v)
    if (rep.remap[v] != vrs::kRemoved) global[rep.remap[v]] = ids[v];
  RecordWriter out(tile_path(dir, level, tile, ".out"));
  FaceRecord r{};
  for (size_t f = 0; f < mesh.face_count(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const uint32_t l = mesh.triangles[3 * f + c];
      r.v[c] = global[l];
      std::memcpy(r.p[c], &mesh.positions[3 * size_t(l)], 12);
    }
    out.write(&r, sizeof r);
  }
  out.commit();
}

Level next_level(const std::string& dir) {
  State s = read_state(dir);
  if (s.count("done")) return level_of(s);
  const int level = int(state_number(s, "level"));
  const uint64_t tiles = uint64_t(state_number(s, "tiles"));
  const uint64_t before = uint64_t(state_number(s, "faces"));
  const uint64_t target = uint64_t(state_number(s, "target"));
  uint64_t faces = 0;
  for (uint64_t t = 0; t < tiles; ++t)
    faces += record_count(tile_path(dir, level, t, ".out"));
  int stalls = double(faces) > 0.995 * double(before) ? int(state_number(s, "stalls")) + 1 : 0;
  s["stalls"] = std::to_string(stalls);
  s["output_faces"] = num(double(faces));
  // Done: at the target, or the whole mesh was one tile (nothing left to release), or levels
  // stopped making progress.
  if (double(faces) <= double(target) * (1 + kSlack) + 2 || tiles == 1 || stalls >= 2 ||
      level >= kMaxLevels) {
    s["done"] = "1";
    write_state(dir, s);
    return level_of(s);
  }
  s["level"] = std::to_string(level + 1);
  s["faces"] = num(double(faces));
  s["ratio"] = num(std::min(1.0, double(target) / double(faces)));
  // What is left fits the whole budget as one tile (run alone): the last level is the
  // in-core run of it, borders and all.
  const uint64_t per_tile = uint64_t(state_number(s, "faces_per_tile"));
  const uint64_t budget = faces <= per_tile * kTilesInMemory ? faces : per_tile;
  s["tiles"] = num(double(partition(dir, level + 1, uint64_t(state_number(s, "vertices")),
                                    box_of(s), budget, level_outputs(dir, level, tiles))));
  write_state(dir, s);
  remove_tree(dir + "/L" + std::to_string(level));
  return level_of(s);
}

uint64_t finish(const std::string& dir, const std::string& output) {
  const State s = read_state(dir);
  if (!s.count("done")) throw std::runtime_error("the tiled run is not done yet");
  const int level = int(state_number(s, "level"));
  const uint64_t tiles = uint64_t(state_number(s, "tiles"));
  const uint64_t vertices = uint64_t(state_number(s, "vertices"));
  const FaceSource faces = level_outputs(dir, level, tiles);
  std::vector<uint32_t> index(vertices, 0); // input vertex -> output index + 1 (0: unused)
  uint64_t face_count = 0;
  faces([&](const FaceRecord& r) {
    for (uint32_t v : r.v)
      index[v] = 1;
    ++face_count;
  });
  uint32_t next = 0;
  for (uint32_t& i : index)
    if (i) i = ++next;
  const bool obj = output.size() >= 4 && (output.compare(output.size() - 4, 4, ".obj") == 0 ||
                                          output.compare(output.size() - 4, 4, ".OBJ") == 0);
  RecordWriter out(output, /*durable=*/true);
  char line[128];
  if (!obj) {
    const std::string header = "ply\nformat binary_little_endian 1.0\ncomment vrsimplify, tiled\n"
                               "element vertex " +
                               std::to_string(next) +
                               "\nproperty float x\nproperty float y\nproperty float z\n"
                               "element face " +
                               std::to_string(face_count) +
                               "\nproperty list uchar int vertex_indices\nend_header\n";
    out.write(header.data(), header.size());
  }
  std::FILE* f = std::fopen((dir + "/vertices.bin").c_str(), "rb");
  if (!f) throw std::runtime_error("cannot read " + dir + "/vertices.bin");
  std::vector<float> buf(3 * 8192);
  size_t n;
  uint64_t v = 0;
  while ((n = std::fread(buf.data(), 12, buf.size() / 3, f)) > 0)
    for (size_t i = 0; i < n; ++i, ++v) {
      if (!index[v]) continue;
      if (obj) {
        const int len = std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", buf[3 * i],
                                      buf[3 * i + 1], buf[3 * i + 2]);
        out.write(line, size_t(len));
      } else {
        out.write(&buf[3 * i], 12);
      }
    }
  std::fclose(f);
  faces([&](const FaceRecord& r) {
    if (obj) {
      const int len = std::snprintf(line, sizeof line, "f %u %u %u\n", index[r.v[0]], index[r.v[1]],
                                    index[r.v[2]]);
      out.write(line, size_t(len));
    } else {
      unsigned char rec[13];
      rec[0] = 3;
      for (int c = 0; c < 3; ++c) {
        const int32_t i = int32_t(index[r.v[c]] - 1);
        std::memcpy(rec + 1 + 4 * c, &i, 4);
      }
      out.write(rec, 13);
    }
  });
  out.commit();
  return face_count;
}

std::string make_work_dir(const std::string& parent) {
  const std::string base = parent.empty() ? "." : parent;
  if (mkdir(base.c_str(), 0755) != 0 && errno != EEXIST)
    throw std::runtime_error("cannot make the work directory " + base + ": " +
                             std::strerror(errno));
  std::string path = base + (base.back() == '/' ? "" : "/") + "vrsimplify-tiles-XXXXXX";
  if (!mkdtemp(path.data()))
    throw std::runtime_error("cannot make a work directory in " + base + ": " +
                             std::strerror(errno));
  return path;
}

void discard(const std::string& workdir) {
  remove_tree(workdir);
}

uint64_t faces_for_memory(uint64_t bytes) {
  // A tile in core: the core's mesh and state (~85 bytes a face at 19 M faces), its records
  // while read (52) and the id sort (12), with room to spare.
  return bytes / kTilesInMemory / 200;
}

bool fits_in_core(uint64_t faces, uint64_t bytes) {
  return faces * 110 <= bytes; // the CLI in core: vcglib's document and the core's mesh
}

uint64_t parse_memory(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (!end || end == text.c_str() || !(v > 0)) return 0;
  const std::string unit = end;
  const double scale = unit == "" || unit == "B"                      ? 1.0
                       : unit == "K" || unit == "KB" || unit == "KiB" ? 1024.0
                       : unit == "M" || unit == "MB" || unit == "MiB" ? 1048576.0
                       : unit == "G" || unit == "GB" || unit == "GiB" ? 1073741824.0
                       : unit == "T" || unit == "TB" || unit == "TiB" ? 1099511627776.0
                                                                      : 0.0;
  return uint64_t(v * scale);
}

std::string check_mesh_file(const std::string& path) {
  std::FILE* in = std::fopen(path.c_str(), "rb");
  if (!in) return std::strerror(errno);
  int64_t vertices = 0, lowest = 0, highest = -1;
  StreamSink sink{[&](const float*) { ++vertices; },
                  [&](const int64_t v[3]) {
                    for (int c = 0; c < 3; ++c)
                      lowest = std::min(lowest, v[c]), highest = std::max(highest, v[c]);
                  }};
  std::string error = read_mesh_stream(in, path, sink);
  std::fclose(in);
  if (error.empty() && (lowest < 0 || highest >= vertices))
    error = "a face's vertex index (" + std::to_string(lowest < 0 ? lowest : highest) +
            ") is out of range: the file has " + std::to_string(vertices) + " vertices";
  return error;
}

} // namespace vrs::tiled
