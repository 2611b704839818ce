// The chain of nested levels (lods.h): simplify, compose each level's maps back to the input,
// then order the vertices coarsest level first.
#include "vrs/lods.h"

#include <algorithm>
#include <unordered_map>

#include "mesh/corner_seams.h"

namespace vrs {

namespace {

// Constrained edges after a run (level numbering before it): a removed vertex on two of them
// was removed along them, so its two neighbours on the polyline are joined.
std::vector<uint32_t> follow_constraints(const std::vector<uint32_t>& edges,
                                         const std::vector<uint32_t>& remap) {
  std::unordered_map<uint32_t, std::vector<uint32_t>> along; // vertex -> its polyline neighbours
  for (size_t i = 0; i + 1 < edges.size(); i += 2) {
    along[edges[i]].push_back(edges[i + 1]);
    along[edges[i + 1]].push_back(edges[i]);
  }
  for (auto& [v, next] : along) {
    if (remap[v] != kRemoved || next.size() != 2) continue;
    const uint32_t a = next[0], b = next[1];
    std::replace(along[a].begin(), along[a].end(), v, b);
    std::replace(along[b].begin(), along[b].end(), v, a);
    next.clear();
  }
  std::vector<uint32_t> out;
  for (const auto& [v, next] : along)
    for (uint32_t w : next)
      if (v < w && remap[v] != kRemoved && remap[w] != kRemoved)
        out.insert(out.end(), {remap[v], remap[w]});
  return out;
}

} // namespace

LodChain simplify_lods(const Mesh& input, std::vector<double> ratios, const Options& options,
                       const std::vector<uint32_t>* corner_keys) {
  LodChain chain;
  if (ratios.empty()) {
    chain.message = "no level asked for";
    return chain;
  }
  for (double r : ratios)
    if (!(r > 0 && r <= 1)) {
      chain.message = "every level's ratio must be in (0, 1]";
      return chain;
    }
  if (corner_keys && corner_keys->size() != input.triangles.size()) {
    chain.message = "corner keys: one per face corner";
    return chain;
  }
  std::sort(ratios.begin(), ratios.end(), std::greater<double>());
  ratios.erase(std::unique(ratios.begin(), ratios.end()), ratios.end());

  Mesh level = input;
  std::vector<uint32_t> ids(input.vertex_count()); // level vertex -> input vertex
  for (uint32_t v = 0; v < ids.size(); ++v)
    ids[v] = v;
  std::vector<uint32_t> faces(input.face_count()), corners(input.triangles.size());
  for (uint32_t f = 0; f < faces.size(); ++f)
    faces[f] = f;
  for (uint32_t c = 0; c < corners.size(); ++c)
    corners[c] = c;
  std::vector<uint32_t> constrained =
      options.constrained_edges ? *options.constrained_edges : std::vector<uint32_t>{};
  std::vector<uint8_t> locked;

  for (double ratio : ratios) {
    Options o = priced_as_input(options, input.face_count());
    o.target = Target{};
    o.target.kind = TargetKind::Faces;
    o.target.faces = static_cast<size_t>(ratio * double(input.face_count()));
    o.corner_sources = corner_keys != nullptr || options.corner_sources;
    std::vector<uint32_t> edges = constrained;
    if (corner_keys) {
      std::vector<uint32_t> keys(corners.size());
      for (size_t c = 0; c < corners.size(); ++c)
        keys[c] = (*corner_keys)[corners[c]];
      const std::vector<uint32_t> seams = key_seams(level, keys);
      edges.insert(edges.end(), seams.begin(), seams.end());
    }
    o.constrained_edges = &edges;
    if (options.locked) {
      locked.assign(ids.size(), 0);
      for (size_t v = 0; v < ids.size(); ++v)
        locked[v] = (*options.locked)[ids[v]];
      o.locked = &locked;
    }
    std::vector<uint8_t> polygon;
    if (options.polygon_faces) { // a level's face the chain left untouched is an input face
      polygon.assign(faces.size(), 0);
      for (size_t f = 0; f < faces.size(); ++f)
        polygon[f] = faces[f] != kRemoved && (*options.polygon_faces)[faces[f]];
      o.polygon_faces = &polygon;
    }
    LodLevel out;
    out.ratio = ratio;
    out.report = simplify(level, o);
    if (!out.report.ok) {
      chain.message = out.report.message;
      return chain;
    }
    const Report& rep = out.report;
    // Compose the maps back to the input.
    std::vector<uint32_t> next_ids(level.vertex_count());
    for (size_t v = 0; v < rep.remap.size(); ++v)
      if (rep.remap[v] != kRemoved) next_ids[rep.remap[v]] = ids[v];
    constrained = follow_constraints(constrained, rep.remap);
    out.face_source.resize(level.face_count());
    for (size_t f = 0; f < out.face_source.size(); ++f)
      out.face_source[f] = rep.face_source[f] == kRemoved ? kRemoved : faces[rep.face_source[f]];
    if (o.corner_sources) {
      out.corner_source.resize(level.triangles.size());
      for (size_t c = 0; c < out.corner_source.size(); ++c)
        out.corner_source[c] = corners[rep.corner_source[c]];
      corners = out.corner_source;
    }
    faces = out.face_source;
    ids = std::move(next_ids);
    out.triangles = level.triangles; // level numbering for now; input ids below
    for (uint32_t& v : out.triangles)
      v = ids[v];
    chain.levels.push_back(std::move(out));
  }

  // The shared order, coarsest level first: each level adds the vertices it references that
  // no coarser level did, in input order.
  std::vector<uint32_t> position(input.vertex_count(), kRemoved);
  for (auto level_it = chain.levels.rbegin(); level_it != chain.levels.rend(); ++level_it) {
    std::vector<uint32_t> added;
    for (uint32_t v : level_it->triangles)
      if (position[v] == kRemoved) {
        position[v] = 0;
        added.push_back(v);
      }
    std::sort(added.begin(), added.end());
    for (uint32_t v : added) {
      position[v] = static_cast<uint32_t>(chain.vertices.size());
      chain.vertices.push_back(v);
    }
    level_it->vertex_count = chain.vertices.size();
  }
  for (LodLevel& l : chain.levels)
    for (uint32_t& v : l.triangles)
      v = position[v];
  chain.ok = true;
  return chain;
}

} // namespace vrs
