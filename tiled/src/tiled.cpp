// The tiled run's steps, each a function of the work directory (see vrs/tiled.h).
#include "vrs/tiled.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include "corner_values.h"
#include "mesh_stream.h"
#include "output_file.h"
#include "partition.h"
#include "tile_files.h"
#include "tile_seams.h"
#include "vrs/simplify.h"

namespace vrs::tiled {

namespace {

constexpr int kMaxLevels = 12;
constexpr double kSlack = 0.005; // done within half a per cent of the target
// The share of the whole budget (kTilesInMemory tiles) the last, single tile is left with:
// the best max error of the shares tried (bench/TILED.md).
constexpr double kLastRoom = 0.5;

// The faces one tile may hold when it runs alone, with the whole budget: three quarters of
// kTilesInMemory tiles' worth, since a lone tile runs on every core and peaks above the bytes a
// face a tile is cut for (with the whole four tiles' worth, a colored scan went over its
// budget).
uint64_t lone_faces(uint64_t per_tile) {
  return per_tile * kTilesInMemory * 3 / 4;
}

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

// Level 1's faces: faces.bin (and keys.bin) with the positions of vertices.bin (held in
// memory meanwhile).
FaceSource input_faces(const std::string& dir, const std::vector<float>& positions, bool keys) {
  return [&dir, &positions, keys](const std::function<void(const FaceRecord&)>& fn) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(
        std::fopen((dir + "/faces.bin").c_str(), "rb"), &std::fclose),
        k(keys ? std::fopen((dir + "/keys.bin").c_str(), "rb") : nullptr, &std::fclose),
        polygons(std::fopen((dir + "/polygons.bin").c_str(), "rb"), &std::fclose);
    if (!f || (keys && !k)) throw std::runtime_error("cannot read the faces in " + dir);
    // The polygons, in face order: the triangles of each are marked (FaceRecord::polygon).
    PolygonRecord poly{};
    auto next_polygon = [&] {
      if (!polygons || std::fread(&poly, sizeof poly, 1, polygons.get()) != 1)
        poly = {~uint64_t(0), 0, 0};
    };
    next_polygon();
    std::vector<uint32_t> buf(3 * 8192);
    std::vector<CornerKeys> kbuf(keys ? 8192 : 0);
    size_t n;
    uint64_t face = 0;
    FaceRecord r{};
    while ((n = std::fread(buf.data(), 12, buf.size() / 3, f.get())) > 0) {
      if (keys && std::fread(kbuf.data(), sizeof(CornerKeys), n, k.get()) != n)
        throw std::runtime_error("cannot read " + dir + "/keys.bin");
      for (size_t i = 0; i < n; ++i, ++face) {
        for (int c = 0; c < 3; ++c) {
          r.v[c] = buf[3 * i + c];
          std::memcpy(r.p[c], &positions[3 * size_t(r.v[c])], 12);
          if (keys) r.a[c] = kbuf[i].a[c], r.b[c] = kbuf[i].b[c];
        }
        if (keys) r.group = kbuf[i].group;
        r.polygon = face >= poly.first;
        fn(r);
        if (r.polygon && face + 3 == poly.first + poly.corners) next_polygon();
      }
    }
  };
}

FaceSource level_outputs(const std::string& dir, int level, uint64_t tiles, bool keys) {
  return [dir, level, tiles, keys](const std::function<void(const FaceRecord&)>& fn) {
    for (uint64_t t = 0; t < tiles; ++t)
      for_each_record(tile_path(dir, level, t, ".out"), keys, fn);
  };
}

bool has_keys(const State& s) {
  return s.count("keys") && s.at("keys") == "1";
}

std::vector<std::string> read_lines(const std::string& path) {
  std::vector<std::string> lines;
  std::ifstream f(path);
  for (std::string line; std::getline(f, line);)
    lines.push_back(line);
  return lines;
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
  l.serial = !s.count("done") && s.count("serial") && s.at("serial") == "1";
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

  // The one streaming pass over the input. Per-corner keys go to keys.bin from the first face
  // that has any (the faces before it get zero keys then); a mesh without them has none.
  Box box{{HUGE_VALF, HUGE_VALF, HUGE_VALF}, {-HUGE_VALF, -HUGE_VALF, -HUGE_VALF}};
  uint64_t vertices = 0, faces = 0, texcoords = 0, normals = 0;
  bool vertex_data = false; // a vertex holds more than its position (split vertices: seam)
  // OBJ normals, one per face (every face's corners name one vn line here, or lines of one
  // value: flat_by_value below): flat shading, which holds nothing the geometry does not (as
  // in core: no seams, the output faces their own).
  const bool obj = format_of(input) == "obj";
  bool normal_keys = false, flat = true, other_keys = false, polygons = false;
  int64_t max_index = -1, min_index = 0;
  std::vector<std::string> materials;
  std::unique_ptr<RecordWriter> kout;
  bool beyond = false, have_origin = false; // see sink.vertex
  double origin[3] = {0, 0, 0};
  {
    RecordWriter vout(dir + "/vertices.bin"), fout(dir + "/faces.bin"), pout(dir + "/polygons.bin");
    StreamSink sink;
    // The tiles see positions as the in-core run does (vrs::float_positions): floats, or, where
    // a float cannot hold a coordinate (georeferenced scans of 4e6 m would leave a float 0.5 m
    // steps), from the first vertex whose coordinates are finite on; which, only the whole
    // file tells: the doubles go to disk, read back as floats once it is known. The output
    // copies the input's vertices, whatever the tiles saw.
    sink.vertex = [&](const double q[3]) {
      if (!have_origin && std::isfinite(q[0]) && std::isfinite(q[1]) && std::isfinite(q[2]))
        have_origin = true, origin[0] = q[0], origin[1] = q[1], origin[2] = q[2];
      for (int a = 0; a < 3 && !beyond; ++a)
        beyond = vrs::beyond_float(q[a]);
      vout.write(q, 24);
      ++vertices;
    };
    sink.triangle = [&](const int64_t v[3], const CornerKeys& k) {
      uint32_t t[3];
      for (int c = 0; c < 3; ++c) {
        max_index = std::max(max_index, v[c]);
        min_index = std::min(min_index, v[c]);
        t[c] = uint32_t(std::min<int64_t>(std::max<int64_t>(v[c], 0), 0xffffffffLL));
      }
      fout.write(t, 12);
      normal_keys |= (k.b[0] | k.b[1] | k.b[2]) != 0;
      flat &= k.b[0] == k.b[1] && k.b[1] == k.b[2];
      other_keys |= (k.group | k.a[0] | k.a[1] | k.a[2]) != 0;
      if (!kout && (k.group | k.a[0] | k.a[1] | k.a[2] | k.b[0] | k.b[1] | k.b[2])) {
        kout = std::make_unique<RecordWriter>(dir + "/keys.bin");
        const CornerKeys none{};
        for (uint64_t f = 0; f < faces; ++f)
          kout->write(&none, sizeof none);
      }
      if (kout) kout->write(&k, sizeof k);
      ++faces;
    };
    sink.uncarried = [&](const std::string& what) {
      throw std::runtime_error("a tiled run cannot carry " + what + " of " + input +
                               ": run it in core (without a memory budget)");
    };
    sink.material = [&](uint32_t, const std::string& name) { materials.push_back(name); };
    // OBJ and OFF polygons come out whole where untouched, as in core (a PLY's are read as
    // triangles there, by vcglib: here too).
    if (format_of(input) != "ply")
      sink.polygon = [&](size_t corners) {
        polygons = true;
        const PolygonRecord r{faces, uint32_t(corners), 0};
        pout.write(&r, sizeof r);
      };
    sink.layout = [&](const Layout& l) {
      for (const std::string& p : l.vertex_properties) {
        const size_t end = p.find_last_not_of(" \t\r");
        const size_t start = p.find_last_of(" \t", end) + 1;
        const std::string name = end == std::string::npos ? "" : p.substr(start, end + 1 - start);
        vertex_data |= name != "x" && name != "y" && name != "z";
      }
      vertex_data |= l.format == Layout::Format::Off && l.off_keyword != "OFF";
    };
    // OBJ: "v x y z [w | r g b]", colours are vertex data (PLY, OFF: their header says).
    if (obj)
      sink.raw_vertex = [&](const char* data, size_t size) {
        if (vertex_data || size < 2 || data[0] != 'v') return;
        int tokens = 0;
        for (size_t i = 0; i < size; ++i)
          tokens += data[i] != ' ' && data[i] != '\t' &&
                    (i == 0 || data[i - 1] == ' ' || data[i - 1] == '\t');
        vertex_data = tokens > 5;
      };
    // OBJ vt and vn values, for the tiles to tell seams by value (corner_values.h).
    RecordWriter vtout(dir + "/texcoords.bin"), vnout(dir + "/normals.bin");
    sink.other_line = [&](const std::string& line) {
      const size_t start = line.find_first_not_of(" \t");
      if (start == std::string::npos) return;
      const char* c = line.c_str() + start;
      const bool vt = c[0] == 'v' && c[1] == 't' && (c[2] == ' ' || c[2] == '\t');
      const bool vn = c[0] == 'v' && c[1] == 'n' && (c[2] == ' ' || c[2] == '\t');
      if (!vt && !vn) return;
      float x[3] = {0, 0, 0}; // missing values read as 0, as vcg reads them
      char* end = const_cast<char*>(c + 2);
      for (int i = 0; i < (vt ? 2 : 3); ++i)
        x[i] = std::strtof(end, &end);
      if (vt) ++texcoords, vtout.write(x, 8);
      if (vn) ++normals, vnout.write(x, 12);
    };
    std::string error;
    try {
      error = read_mesh_stream(in, input, sink);
    } catch (...) {
      std::fclose(in);
      throw;
    }
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
    pout.commit();
    vtout.commit();
    vnout.commit();
    if (kout) kout->commit();
  }
  // Flat shading as the in-core run tells it: one normal value at every face's corners (a
  // file may write it on three vn lines).
  if (obj && normal_keys && !flat && kout)
    flat = flat_by_value(dir + "/keys.bin", faces, CornerValues(dir + "/normals.bin", 3));
  if (!materials.empty()) {
    RecordWriter m(dir + "/materials");
    for (const std::string& name : materials)
      m.write((name + "\n").data(), name.size() + 1);
    m.commit();
  }
  if (faces == 0) throw std::runtime_error("cannot read " + input + ": the mesh has no faces");

  State s;
  s["input"] = input;
  const bool flat_normals = obj && normal_keys && flat;
  s["flat_normals"] = flat_normals ? "1" : "0";
  const bool corner_data = other_keys || (normal_keys && !flat_normals);
  // Keys only for what they hold: flat normals alone need none (the tiles then stay as large
  // as those of a mesh without any).
  const bool keyed = kout && corner_data;
  s["keys"] = keyed ? "1" : "0";
  s["polygons"] = polygons ? "1" : "0";
  const std::string& split = settings.split_vertices;
  if (!split.empty() && split != "seam" && split != "weld" && split != "keep")
    throw std::runtime_error("split_vertices must be seam, weld or keep, got " + split);
  s["split"] = !split.empty() ? split : vertex_data || corner_data ? "seam" : "weld";
  s["texcoords"] = num(double(texcoords));
  s["normals"] = num(double(normals));
  s["vertices"] = num(double(vertices));
  s["input_faces"] = num(double(faces));
  s["faces"] = num(double(faces));
  s["target"] = num(std::floor(settings.ratio * double(faces)));
  s["ratio"] = num(settings.ratio);
  // Tiles with per-corner data also hold their keys, seams and corner sources while they run:
  // measured 315 bytes a face at the peak of a lone tile against 200 without (5.7 M faces, 10 %).
  const uint64_t per_tile = keyed ? settings.faces_per_tile * 200 / 320 : settings.faces_per_tile;
  s["faces_per_tile"] = num(double(per_tile));
  s["level"] = "1";
  s["stalls"] = "0";
  {
    // The doubles as floats, a block at a time (the rule of vrs::float_positions), and the
    // box of what the tiles see.
    std::vector<float> positions(3 * vertices);
    std::FILE* f = std::fopen((dir + "/vertices.bin").c_str(), "rb");
    std::vector<double> block(3 * 65536);
    size_t got = 0;
    for (size_t n;
         f && got < vertices &&
         (n = std::fread(block.data(), 24, std::min<size_t>(65536, vertices - got), f)) > 0;
         got += n)
      for (size_t i = 0; i < 3 * n; ++i) {
        const float p = float(block[i] - (beyond ? origin[i % 3] : 0.0));
        positions[3 * got + i] = p;
        if (std::isfinite(p))
          box.lo[i % 3] = std::min(box.lo[i % 3], p), box.hi[i % 3] = std::max(box.hi[i % 3], p);
      }
    if (f) std::fclose(f);
    if (got != vertices) throw std::runtime_error("cannot read back " + dir + "/vertices.bin");
    for (int a = 0; a < 3; ++a) {
      if (!(box.lo[a] <= box.hi[a])) box.lo[a] = box.hi[a] = 0;
      s["lo" + std::to_string(a)] = num(box.lo[a]);
      s["hi" + std::to_string(a)] = num(box.hi[a]);
    }
    // A mesh that fits the whole budget is one tile at once (what the last level would be).
    const uint64_t budget = faces <= lone_faces(per_tile) ? faces : per_tile;
    s["tiles"] = num(double(partition(dir, 1, vertices, box, budget, keyed, false,
                                      input_faces(dir, positions, keyed))));
  }
  // In the tiles now; the disk is the next level's (the faces stay for the polygons).
  if (!polygons) std::remove((dir + "/faces.bin").c_str());
  std::remove((dir + "/keys.bin").c_str());
  write_state(dir, s);
  return level_of(s);
}

void run_tile(const std::string& dir, int level, uint64_t tile, int lone_threads) {
  const State s = read_state(dir);
  const bool keyed = has_keys(s);
  std::vector<FaceRecord> in;
  for_each_record(tile_path(dir, level, tile, ".in"), keyed,
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
  // Flat normals are no seam, and the output gives each face its own (write_output); other
  // corner data is told apart by value (corner_values.h).
  const bool flat = s.count("flat_normals") && s.at("flat_normals") == "1";
  const CornerValues vt(dir + "/texcoords.bin", 2), vn(dir + "/normals.bin", 3);
  TileKeys keys;
  keys.texcoords = &vt, keys.normals = &vn;
  if (keyed)
    keys.a.resize(3 * in.size()), keys.b.resize(3 * in.size()), keys.group.resize(in.size()),
        keys.seam_sides.resize(in.size());
  for (size_t f = 0; f < in.size(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const uint32_t l = local(in[f].v[c]);
      mesh.triangles[3 * f + c] = l;
      std::memcpy(&mesh.positions[3 * size_t(l)], in[f].p[c], 12);
      if (in[f].shared) locked[l] = 1;
      if (keyed) keys.a[3 * f + c] = in[f].a[c], keys.b[3 * f + c] = flat ? 0 : in[f].b[c];
    }
    if (keyed) keys.group[f] = in[f].group, keys.seam_sides[f] = in[f].seam_sides;
  }
  // Polygons' triangles: the slide leaves them as they are, so untouched polygons stay whole.
  std::vector<uint8_t> polygon(in.size(), 0);
  bool polygons = false;
  for (size_t f = 0; f < in.size(); ++f)
    polygons |= (polygon[f] = in[f].polygon) != 0;
  // On the first two levels the ratio applies to the faces the tile may change: asking the
  // faces along its locked border to go too makes the rest of the tile go further than the
  // target asks (more mean error, measured); the next level, shifted,
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
  opt.relax_to_reach_target = alone || (s.count("serial") && s.at("serial") == "1");
  // A tile's cut is a border of its piece but no border of the mesh: only the whole mesh (the
  // last level, in core) judges whether the border needs simplifying.
  opt.simplify_boundary_when_needed = alone;
  const bool serial = s.count("serial") && s.at("serial") == "1";
  opt.threads = alone || serial ? std::max(0, lone_threads) : 1;
  // Priced as the whole mesh is in core, not by the tile's size (an older work directory
  // without the count: a mesh large enough to be tiled).
  opt = vrs::priced_as_input(opt, s.count("input_faces") ? size_t(state_number(s, "input_faces"))
                                                         : std::numeric_limits<size_t>::max());
  opt.locked = &locked;
  // Split vertices as the run was told at its start (an older work directory: seam).
  const std::string split = s.count("split") ? s.at("split") : "seam";
  opt.split_vertices = split == "weld"   ? vrs::SplitVertices::Weld
                       : split == "keep" ? vrs::SplitVertices::Keep
                                         : vrs::SplitVertices::Seam;
  // Per-corner data: its seams are kept as in core (welded freely, across split edges too:
  // the faces read through the copies that stand for them), and each output corner takes the
  // keys of the input corner the core names.
  std::vector<uint32_t> seams;
  if (keyed && opt.split_vertices == vrs::SplitVertices::Weld) {
    vrs::Mesh welded; // tile_seams reads the faces only
    welded.triangles = vrs::split_vertex_welded_triangles(mesh);
    seams = tile_seams(welded, keys);
  } else if (keyed) {
    seams = tile_seams(mesh, keys);
  }
  opt.constrained_edges = keyed ? &seams : nullptr;
  opt.corner_sources = keyed;
  if (polygons) opt.polygon_faces = &polygon;
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
      if (keyed) {
        const uint32_t from = rep.corner_source[3 * f + c];
        r.a[c] = keys.a[from], r.b[c] = keys.b[from];
      }
    }
    if (keyed) r.group = keys.group[rep.corner_source[3 * f] / 3];
    r.seam_sides = rep.constrained_sides.empty() ? 0 : rep.constrained_sides[f];
    r.polygon = rep.face_source[f] != vrs::kRemoved && polygon[rep.face_source[f]];
    out.write(&r, record_size(keyed));
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
  const bool keyed = has_keys(s);
  uint64_t faces = 0;
  for (uint64_t t = 0; t < tiles; ++t)
    faces += record_count(tile_path(dir, level, t, ".out"), keyed);
  int stalls = double(faces) > 0.995 * double(before) ? int(state_number(s, "stalls")) + 1 : 0;
  s["stalls"] = std::to_string(stalls);
  s["output_faces"] = num(double(faces));
  // Done: at the target, or the whole mesh was one tile (nothing left to release), or levels
  // stopped making progress (after a stall, grown tiles get two tries: the octree's origin
  // moves between them).
  if (double(faces) <= double(target) * (1 + kSlack) + 2 || tiles == 1 || stalls >= 3 ||
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
  // After a level that stalled, tiles are halves of up to a lone tile's budget (the octree's
  // leaves hold an eighth of a budget to a budget, and where the leaves were small their
  // locked borders kept the rest from going: a noisy terrain in tiles of 1 310 faces stalled
  // at 4 times its target) and run one at a time.
  const bool grow = stalls > 0 && faces > lone_faces(per_tile);
  const uint64_t budget = faces <= lone_faces(per_tile) ? faces
                          : grow                        ? lone_faces(per_tile)
                                                        : per_tile;
  s["serial"] = grow ? "1" : "0";
  s["tiles"] =
      num(double(partition(dir, level + 1, uint64_t(state_number(s, "vertices")), box_of(s), budget,
                           keyed, grow, level_outputs(dir, level, tiles, keyed))));
  write_state(dir, s);
  remove_tree(dir + "/L" + std::to_string(level));
  return level_of(s);
}

uint64_t finish(const std::string& dir, const std::string& output) {
  const State s = read_state(dir);
  if (!s.count("done")) throw std::runtime_error("the tiled run is not done yet");
  const int level = int(state_number(s, "level"));
  const uint64_t tiles = uint64_t(state_number(s, "tiles"));
  const FaceSource faces = level_outputs(dir, level, tiles, has_keys(s));
  std::unique_ptr<OutputPolygons> polygons;
  if (s.count("polygons") && s.at("polygons") == "1")
    polygons = std::make_unique<OutputPolygons>(dir, faces);
  return write_output(s.at("input"), output, uint64_t(state_number(s, "vertices")),
                      uint64_t(state_number(s, "texcoords")), uint64_t(state_number(s, "normals")),
                      s.count("flat_normals") && s.at("flat_normals") == "1",
                      read_lines(dir + "/materials"), faces, polygons.get());
}

std::string output_refusal(const std::string& input, const std::string& output) {
  const std::string in = format_of(input), out = format_of(output);
  if (in.empty()) return "a tiled run reads .ply, .obj or .off: cannot read " + input;
  if (out != in)
    return "a tiled run writes the input's own format, so that every attribute and every "
           "coordinate passes untouched: name the output ." +
           in + " (convert it in core, without a memory budget)";
  return {};
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
  StreamSink sink;
  sink.vertex = [&](const double*) { ++vertices; };
  sink.triangle = [&](const int64_t v[3], const CornerKeys&) {
    for (int c = 0; c < 3; ++c)
      lowest = std::min(lowest, v[c]), highest = std::max(highest, v[c]);
  };
  std::string error = read_mesh_stream(in, path, sink);
  std::fclose(in);
  if (error.empty() && (lowest < 0 || highest >= vertices))
    error = "a face's vertex index (" + std::to_string(lowest < 0 ? lowest : highest) +
            ") is out of range: the file has " + std::to_string(vertices) + " vertices";
  return error;
}

} // namespace vrs::tiled
