#include "glb_output.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <unordered_map>

#include "mesh_io.h"
#include "vcg_mesh.h"
#include "vrs/glb.h"
#include "vrs/lods.h"
#include "vrs/progressive.h"
#include <wrap/io_trimesh/io_mask.h>

namespace vrs_tool {

namespace fs = std::filesystem;

bool parse_lods(const std::string& text, std::vector<double>& ratios) {
  ratios.clear();
  char* end = nullptr;
  const long count = std::strtol(text.c_str(), &end, 10);
  if (end && *end == 0 && text.find('.') == std::string::npos) { // a count: a halving chain
    if (count < 1 || count > 24) return false;
    for (long i = 0; i < count; ++i)
      ratios.push_back(std::ldexp(1.0, int(-i)));
    return true;
  }
  std::stringstream s(text);
  std::string item;
  while (std::getline(s, item, ',')) {
    const double r = std::strtod(item.c_str(), &end);
    if (item.empty() || *end || !(r > 0 && r <= 1)) return false;
    ratios.push_back(r);
  }
  return !ratios.empty();
}

namespace {

using vcg::tri::io::Mask;

// The image files the OBJ's materials name (map_Kd), by material name.
std::map<std::string, std::string> obj_textures(const std::string& input,
                                                const std::string& library) {
  std::map<std::string, std::string> out;
  if (library.empty()) return out;
  std::ifstream f(fs::path(input).parent_path() / library);
  std::string line, current;
  while (std::getline(f, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "newmtl") std::getline(s >> std::ws, current);
    if (tag == "map_Kd") {
      std::string file;
      std::getline(s >> std::ws, file); // the last word is the file (options come first)
      const size_t space = file.rfind(' ');
      out[current] = space == std::string::npos ? file : file.substr(space + 1);
    }
  }
  return out;
}

// The one base color image of the input, relative to the output's folder ("" for none), or an
// error when the faces use several.
bool texture_uri(const GlbRequest& r, const VcgDocument& doc, std::string& uri, std::string& err) {
  std::vector<std::string> files;
  if (!doc.mesh.textures.empty()) files = doc.mesh.textures; // PLY: comment TextureFile
  if (!doc.materials.empty()) {
    const auto maps = obj_textures(r.input, doc.material_library);
    for (const std::string& m : doc.materials) {
      auto it = maps.find(m);
      if (it != maps.end() && std::find(files.begin(), files.end(), it->second) == files.end())
        files.push_back(it->second);
    }
  }
  if (files.size() > 1) {
    err = "the input uses " + std::to_string(files.size()) +
          " texture images; a .glb is written with one material (merge them into one atlas "
          "first)";
    return false;
  }
  uri.clear();
  if (files.empty()) return true;
  std::error_code ec;
  const fs::path image = fs::absolute(fs::path(r.input).parent_path() / files[0], ec);
  const fs::path out_dir = fs::absolute(fs::path(r.output), ec).parent_path();
  uri = fs::relative(image, out_dir, ec).generic_string();
  if (ec || uri.empty()) uri = image.generic_string();
  return true;
}

// What the document holds, as the writer's arrays (per input vertex, per input corner).
struct Arrays {
  std::vector<float> normals, colors, uvs, corner_normals, corner_colors, corner_uvs;
  std::vector<uint32_t> corner_keys; // equal keys: same per-corner data (seams between)
};

Arrays arrays_of(const VcgDocument& doc) {
  const VcgMesh& m = doc.mesh;
  const vrs_vcg::CornerData d = doc.corner_data();
  Arrays a;
  if (doc.mask & Mask::IOM_VERTNORMAL)
    for (const Vertex& v : m.vert)
      a.normals.insert(a.normals.end(), {v.cN()[0], v.cN()[1], v.cN()[2]});
  if (doc.mask & Mask::IOM_VERTCOLOR)
    for (const Vertex& v : m.vert)
      for (int c = 0; c < 4; ++c)
        a.colors.push_back(v.cC()[c] / 255.0f);
  if (doc.mask & Mask::IOM_VERTTEXCOORD)
    for (const Vertex& v : m.vert)
      a.uvs.insert(a.uvs.end(), {v.cT().U(), v.cT().V()});
  // Per corner: texture coordinates, smooth normals (flat ones are the faces' own: glTF
  // viewers shade a primitive without normals flat), face colors.
  const bool normals = d.normal && !d.flat_normals;
  std::unordered_map<std::string, uint32_t> keys;
  for (const Face& f : m.face) {
    if (f.IsD()) continue;
    for (int c = 0; c < 3; ++c) {
      std::string key;
      auto add = [&](const void* p, size_t n) { key.append(static_cast<const char*>(p), n); };
      if (d.texcoord) {
        const float uv[2] = {f.cWT(c).U(), f.cWT(c).V()};
        a.corner_uvs.insert(a.corner_uvs.end(), {uv[0], uv[1]});
        add(uv, sizeof uv);
      }
      if (normals) {
        const float n[3] = {f.cWN(c)[0], f.cWN(c)[1], f.cWN(c)[2]};
        a.corner_normals.insert(a.corner_normals.end(), {n[0], n[1], n[2]});
        add(n, sizeof n);
      }
      if (d.face_color) {
        const vcg::Color4b color = f.cC();
        for (int k = 0; k < 4; ++k)
          a.corner_colors.push_back(color[k] / 255.0f);
        add(&color[0], 4);
      }
      if (d.texcoord || normals || d.face_color)
        a.corner_keys.push_back(keys.emplace(key, uint32_t(keys.size())).first->second);
    }
  }
  return a;
}

const float* or_null(const std::vector<float>& v) {
  return v.empty() ? nullptr : v.data();
}

using Clock = std::chrono::steady_clock;

// --progressive: the base and the records, one .glb.
int run_progressive(const GlbRequest& r, const vrs::Mesh& mesh, const Arrays& a,
                    const vrs::GlbAttributes& g, Clock::time_point t0) {
  vrs::Options o = r.options;
  o.target = vrs::Target{};
  o.target.kind = vrs::TargetKind::Ratio;
  o.target.ratio = r.ratios.at(0);
  const auto t1 = Clock::now();
  const vrs::ProgressiveMesh p =
      vrs::simplify_progressive(mesh, o, a.corner_keys.empty() ? nullptr : &a.corner_keys);
  const double seconds = std::chrono::duration<double>(Clock::now() - t1).count();
  if (!p.ok) {
    std::fprintf(stderr, "vrsimplify: %s\n", p.message.c_str());
    return 1;
  }
  vrs::ProgressiveLayout layout;
  const std::string err = vrs::write_progressive_glb(
      r.output, mesh.positions.data(), mesh.vertex_count(), mesh.triangles, p, g, &layout);
  if (!err.empty()) {
    std::fprintf(stderr, "vrsimplify: %s\n", err.c_str());
    return err.rfind("cannot write", 0) == 0 ? 3 : 1;
  }
  const double total = std::chrono::duration<double>(Clock::now() - t0).count();
  const vrs::Report& rep = p.report;
  if (r.json) {
    std::printf("{\"input_vertices\":%zu,\"input_faces\":%zu,\"file_bytes\":%zu,"
                "\"base_bytes\":%zu,\"base_faces\":%zu,\"base_vertices\":%zu,"
                "\"gltf_vertices\":%zu,\"faces\":%zu,\"insertions\":%zu,"
                "\"record_topology_bytes\":%zu,\"target_reached\":%s,\"stop_reason\":\"%s\","
                "\"seconds_simplify\":%.6f,\"seconds_total\":%.6f}\n",
                mesh.vertex_count(), mesh.face_count(), layout.file_bytes, layout.base_bytes,
                layout.base_faces, layout.base_vertices, layout.vertex_count, layout.faces,
                layout.insertions, layout.record_topology_bytes,
                rep.target_reached ? "true" : "false", vrs::stop_reason_name(rep.stop), seconds,
                total);
    return 0;
  }
  std::printf("input:   %zu vertices, %zu faces\n", mesh.vertex_count(), mesh.face_count());
  std::printf("output:  %s, %zu bytes, %zu glTF vertices (split at seams), %zu faces\n",
              r.output.c_str(), layout.file_bytes, layout.vertex_count, layout.faces);
  std::printf("base:    %zu faces, %zu vertices, drawn from %zu bytes (%.1f %%)%s%s\n",
              layout.base_faces, layout.base_vertices, layout.base_bytes,
              100.0 * double(layout.base_bytes) / double(layout.file_bytes),
              rep.target_reached ? "" : ", stopped short: ",
              rep.target_reached ? "" : rep.stop_detail.c_str());
  std::printf("records: %zu insertions, %zu bytes (%zu of them faces, %.1f a vertex; the rest "
              "the vertices)\n",
              layout.insertions, layout.stream_bytes, layout.record_topology_bytes,
              layout.insertions ? double(layout.record_topology_bytes) / double(layout.insertions)
                                : 0.0);
  std::printf("time:    %.3f s simplify, %.3f s total\n", seconds, total);
  return 0;
}

} // namespace

int run_glb(const GlbRequest& r) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  LoadResult loaded = load(r.input);
  if (!loaded.doc) {
    std::fprintf(stderr, "vrsimplify: %s\n", loaded.error.c_str());
    return 3;
  }
  const vrs::Mesh mesh = to_core(*loaded.doc);
  std::string uri, err;
  if (!texture_uri(r, *loaded.doc, uri, err)) {
    std::fprintf(stderr, "vrsimplify: %s\n", err.c_str());
    close(loaded.doc);
    return 1;
  }
  const Arrays a = arrays_of(*loaded.doc);
  close(loaded.doc);

  vrs::GlbAttributes g;
  g.normals = or_null(a.normals);
  g.colors = or_null(a.colors);
  g.uvs = or_null(a.uvs);
  g.corner_normals = or_null(a.corner_normals);
  g.corner_colors = or_null(a.corner_colors);
  g.corner_uvs = or_null(a.corner_uvs);
  g.texture_uri = uri;
  g.generator = std::string("vrsimplify ") + VRS_VERSION;
  g.compress = r.compress;
  if (r.progressive) return run_progressive(r, mesh, a, g, t0);

  vrs::Options o = r.options;
  if (r.error_bound && !(o.max_error > 0)) o.max_error = HUGE_VAL;
  const auto t1 = clock::now();
  const vrs::LodChain chain =
      vrs::simplify_lods(mesh, r.ratios, o, a.corner_keys.empty() ? nullptr : &a.corner_keys);
  const double seconds = std::chrono::duration<double>(clock::now() - t1).count();
  if (!chain.ok) {
    std::fprintf(stderr, "vrsimplify: %s\n", chain.message.c_str());
    return 1;
  }
  // Each level's bound is against the finer level: against the input they add up.
  std::vector<double> bounds;
  double sum = 0;
  for (const vrs::LodLevel& l : chain.levels) {
    sum += l.report.error_bound;
    bounds.push_back(r.error_bound ? sum : -1.0);
  }
  g.level_errors = bounds;
  vrs::GlbLayout layout;
  err = vrs::write_glb(r.output, mesh.positions.data(), mesh.vertex_count(), chain, g, &layout);
  if (!err.empty()) { // the file system's refusal (3), or what glTF cannot hold (1)
    std::fprintf(stderr, "vrsimplify: %s\n", err.c_str());
    return err.rfind("cannot write", 0) == 0 ? 3 : 1;
  }
  const double total = std::chrono::duration<double>(clock::now() - t0).count();
  if (r.json) {
    std::printf("{\"input_vertices\":%zu,\"input_faces\":%zu,\"file_bytes\":%zu,"
                "\"gltf_vertices\":%zu,\"compressed\":%s,\"seconds_simplify\":%.6f,"
                "\"seconds_total\":%.6f,\"levels\":[",
                mesh.vertex_count(), mesh.face_count(), layout.file_bytes, layout.vertex_count,
                layout.compressed ? "true" : "false", seconds, total);
    for (size_t k = 0; k < chain.levels.size(); ++k) {
      const auto& l = chain.levels[k];
      const auto& L = layout.levels[k];
      std::printf("%s{\"ratio\":%.17g,\"faces\":%zu,\"vertices\":%zu,\"bytes_to_draw\":%zu,"
                  "\"target_reached\":%s,\"stop_reason\":\"%s\"",
                  k ? "," : "", l.ratio, L.faces, L.vertex_count, L.bytes_to_draw,
                  l.report.target_reached ? "true" : "false", vrs::stop_reason_name(l.report.stop));
      if (r.error_bound) std::printf(",\"error_bound\":%.9g", bounds[k]);
      std::printf("}");
    }
    std::printf("]}\n");
    return 0;
  }
  std::printf("input:   %zu vertices, %zu faces\n", mesh.vertex_count(), mesh.face_count());
  std::printf("output:  %s, %zu levels, %zu bytes%s, %zu glTF vertices (split at seams%s)\n",
              r.output.c_str(), chain.levels.size(), layout.file_bytes,
              layout.compressed ? " (EXT_meshopt_compression)" : "", layout.vertex_count,
              layout.compressed ? ", padded to the codec's blocks" : "");
  for (size_t k = 0; k < chain.levels.size(); ++k) {
    const auto& l = chain.levels[k];
    const auto& L = layout.levels[k];
    std::printf("level %zu: ratio %g, %zu faces, %zu vertices, drawn from %zu bytes (%.1f %%)", k,
                l.ratio, L.faces, L.vertex_count, L.bytes_to_draw,
                100.0 * double(L.bytes_to_draw) / double(layout.file_bytes));
    if (r.error_bound) std::printf(", error bound %.6g", bounds[k]);
    if (!l.report.target_reached) std::printf(", stopped short: %s", l.report.stop_detail.c_str());
    std::printf("\n");
  }
  std::printf("time:    %.3f s simplify, %.3f s total\n", seconds, total);
  return 0;
}

} // namespace vrs_tool
