// Read and classify: degenerate faces out, spatial order, locks, topology, orientation,
// constraints, normals, then every vertex's kind and first price.
#include <algorithm>
#include <limits>

#include "driver/simplifier.h"
#include "evaluate/local_error.h"
#include "mesh/orientation.h"
#include "mesh/split_vertices.h"

namespace vrs {

namespace {

constexpr uint8_t kKeptOnConstraints = 128; // beside a VertexKind in the set-up's kinds

size_t drop_repeated_corner_faces(std::vector<uint32_t>& tris, UninitVector<uint32_t>& source,
                                  Workers* workers) {
  // Counted in blocks on the workers; with none to drop (the usual input) each face is its own
  // source, written in blocks too.
  constexpr size_t kBlock = 65536;
  const size_t faces = tris.size() / 3;
  std::vector<size_t> repeated((faces + kBlock - 1) / kBlock, 0);
  for_each_block(workers, faces, kBlock, [&](size_t begin, size_t end) {
    for (size_t f = begin; f < end; ++f) {
      const uint32_t a = tris[3 * f], b = tris[3 * f + 1], c = tris[3 * f + 2];
      repeated[begin / kBlock] += a == b || b == c || c == a;
    }
  });
  if (std::all_of(repeated.begin(), repeated.end(), [](size_t r) { return r == 0; })) {
    source.resize(faces);
    for_each_block(workers, faces, kBlock, [&](size_t begin, size_t end) {
      for (size_t f = begin; f < end; ++f)
        source[f] = static_cast<uint32_t>(f);
    });
    return 0;
  }
  size_t out = 0;
  source.clear();
  source.reserve(tris.size() / 3);
  for (size_t i = 0; i < tris.size(); i += 3) {
    uint32_t a = tris[i], b = tris[i + 1], c = tris[i + 2];
    if (a == b || b == c || c == a) continue;
    source.push_back(static_cast<uint32_t>(i / 3));
    tris[out++] = a;
    tris[out++] = b;
    tris[out++] = c;
  }
  size_t dropped = (tris.size() - out) / 3;
  tris.resize(out);
  return dropped;
}

} // namespace

bool Simplifier::border_needs_simplifying() {
  if (!target_faces_ && !target_vertices_) return false;
  const auto& t = mesh_.triangles;
  // Counted in blocks on the workers (every vertex's ring: a sixth of the serial set-up).
  constexpr size_t kBlock = 16384;
  const size_t n = mesh_.vertex_count(), blocks = (n + kBlock - 1) / kBlock;
  std::vector<std::pair<size_t, size_t>> counts(blocks); // (border, used)
  workers_.for_each(
      blocks,
      [&](size_t b) {
        Ring ring;
        for (size_t v = b * kBlock; v < std::min(n, (b + 1) * kBlock); ++v) {
          const VertexKind k = topo_.ring(uint32_t(v), t.data(), opt_.max_valence, ring);
          counts[b].second += k != VertexKind::Isolated;
          counts[b].first += k == VertexKind::Boundary || k == VertexKind::Corner;
        }
      },
      1);
  size_t border = 0, used = 0;
  for (const auto& c : counts)
    border += c.first, used += c.second;
  // Keeping B border vertices, a surface of V vertices and F faces needs 2B - 2V + F faces
  // at least (Euler). Past a quarter of the target, the interior is all that is left to spend
  // (a half or the whole target as the threshold left open meshes' tail worse).
  return border_takes(border, used, 0.25);
}

bool Simplifier::border_takes(size_t border, size_t used, double share) const {
  const double least = 2.0 * double(border) - 2.0 * double(used) + double(faces0_);
  return (target_faces_ && least > share * double(target_faces_)) ||
         (target_vertices_ && double(border) > share * double(target_vertices_));
}

void Simplifier::lock_split_seams() {
  // Border vertices at exactly the position of another border vertex: a seam written as split
  // vertices (meshes loaded for rendering, trimesh's UV seams). Each side is a border of its
  // own; simplified apart, the two would open a crack. They stay, as without the border rule.
  const auto& t = mesh_.triangles;
  std::vector<uint32_t> border;
  Ring ring;
  for (uint32_t v = 0; v < mesh_.vertex_count(); ++v) {
    const VertexKind k = topo_.ring(v, t.data(), opt_.max_valence, ring);
    if (k == VertexKind::Boundary || k == VertexKind::Corner) border.push_back(v);
  }
  const float* p = mesh_.positions.data();
  auto less = [p](uint32_t a, uint32_t b) {
    return std::lexicographical_compare(p + 3 * size_t(a), p + 3 * size_t(a) + 3, p + 3 * size_t(b),
                                        p + 3 * size_t(b) + 3);
  };
  auto same = [p](uint32_t a, uint32_t b) {
    return std::equal(p + 3 * size_t(a), p + 3 * size_t(a) + 3, p + 3 * size_t(b));
  };
  std::sort(border.begin(), border.end(), less);
  // Copies of one vertex (fan_split.h) are no seam: one vertex of the input.
  for (size_t i = 0; i + 1 < border.size(); ++i)
    if (same(border[i], border[i + 1]) && !topo_.same_vertex(border[i], border[i + 1]))
      flags_[border[i]] |= kFlagTwin | kFlagLocked,
          flags_[border[i + 1]] |= kFlagTwin | kFlagLocked;
}

// The set-up that reads the fans, up to every vertex's kind and first price: made again when
// fans were split apart (the run's numbering then has the copies).
void Simplifier::first_prices(UninitVector<uint8_t>& kinds, UninitVector<FirstPrice>& first) {
  const size_t n = mesh_.vertex_count();
  const auto& t = mesh_.triangles;
  // The normal cones and fan areas vertex by vertex on the workers (summed face by face on
  // one thread, they were a fifth of the run's serial part).
  normals_.resize(4 * n);
  if (lazy_) {
    fan_area_.resize(n);
    fill_on(&workers_, chosen_, n, kNoCandidate);
  }
  workers_.for_each(
      n,
      [&](size_t v) {
        vertex_cone(mesh_.positions.data(), t.data(), topo_, uint32_t(v), &normals_[4 * v],
                    lazy_ ? &fan_area_[v] : nullptr);
      },
      1024);
  reference_area_ = mean_triangle_area(mesh_.positions.data(), t, &workers_);
  // A thousandth of the area asked, a patch refused past a two-thousandth folded (refused at
  // any folded point, the thin CAD shells lost more error than the folds cost).
  const double input_area = reference_area_ * double(t.size() / 3);
  limits_.large_triangle_area = 1e-3 * input_area;
  limits_.fold_budget = 5e-4 * input_area;
  planner_ =
      Planner(eval_, topo_, t.data(), normals_.data(), limits_, Pricer{&estimate, &price, this},
              opt_.tuning.fill == Fill::Best, opt_.mode != Mode::Surface3D);
  if (opt_.max_error > 0) {
    face_bound_.assign(t.size() / 3, 0.0f); // the input is its own surface
    limits_.max_error = opt_.max_error;
    planner_.set_face_bounds(face_bound_.data());
  }
  if (opt_.tuning.against_input && opt_.tuning.priority == Priority::LocalError) {
    carried_.init(t.size() / 3, n, &workers_);
    planner_.set_carried(&carried_);
  }
  jump_floor_ = 1e-3 * bounding_box_diagonal(mesh_);
  fill_on(&workers_, priority_, n, std::numeric_limits<float>::infinity());
  faces_ = faces0_ = t.size() / 3;
  const TargetKind tk = opt_.target.kind;
  target_faces_ = tk == TargetKind::Faces ? opt_.target.faces
                  : tk == TargetKind::Ratio
                      ? static_cast<size_t>(std::llround(opt_.target.ratio * faces0_))
                      : 0;
  target_vertices_ = tk == TargetKind::Vertices ? opt_.target.vertices : 0;
  rep_.target_faces = target_faces_, rep_.target_vertices = target_vertices_;
  if (!simplify_boundary_ && opt_.simplify_boundary_when_needed &&
      (simplify_boundary_ = rep_.boundary_simplified = border_needs_simplifying()))
    lock_split_seams();
  // Every vertex's kind and first price, on the workers (reads only; each writes its own
  // slots); the caller counts them in vertex order.
  kinds.resize(n);
  first.resize(n);
  slide_.target.assign(n, 0);
  workers_.for_each(
      n,
      [&](size_t i) {
        const uint32_t v = static_cast<uint32_t>(i);
        Ring ring;
        VertexKind kind = topo_.ring(v, t.data(), opt_.max_valence, ring);
        kinds[v] = static_cast<uint8_t>(kind);
        if (kind == VertexKind::Isolated || flags_[v] & kFlagLocked || !removable(kind)) return;
        std::array<int, 2> seam;
        const Along where = along(v, ring, seam);
        // A place a kept vertex may slide onto after the run (slide.cpp): an interior vertex
        // on no constrained edge (no seam, crease or orientation border through it).
        slide_.target[v] = kind == VertexKind::Interior && where == Along::Free;
        if (where == Along::Kept)
          kinds[v] |= kKeptOnConstraints;
        else {
          const Priced p = evaluate(v, ring);
          first[v] = {p.priority, p.why, p.planned};
        }
      },
      256);
}

bool Simplifier::split_fans_apart(const UninitVector<uint8_t>& kinds) {
  // Not with constraints (their edges name the vertices as they were), nor where faces were
  // reoriented (which faces make a fan then follows the orientation chosen; a fuzzer's mesh
  // of pieces so turned changed topology), nor a second time.
  if (constraints_.active() || rep_.reoriented_faces > 0 || !fans_.empty()) return false;
  std::vector<uint32_t> candidates;
  for (uint32_t v = 0; v < kinds.size(); ++v)
    if ((kinds[v] == uint8_t(VertexKind::NonManifold) ||
         kinds[v] == uint8_t(VertexKind::HighValence)) && // its fans may each be small
        !(flags_[v] & kFlagLocked))
      candidates.push_back(v);
  if (candidates.empty()) return false;
  fans_ = split_fans(mesh_.triangles, mesh_.vertex_count(), topo_, candidates);
  if (fans_.empty()) return false;
  // The copies' positions after the input's (compact() takes them off again).
  auto& pos = mesh_.positions;
  pos.reserve(pos.size() + 3 * fans_.original.size());
  for (uint32_t o : fans_.original)
    for (int c = 0; c < 3; ++c)
      pos.push_back(pos[3 * size_t(o) + c]);
  eval_.set_positions(pos.data());
  for (uint32_t o : fans_.original)
    flags_.push_back(flags_[o]);
  topo_.build(mesh_.triangles, mesh_.vertex_count(), &workers_);
  topo_.set_siblings(&fans_.sibling);
  return true;
}

void Simplifier::prepare() {
  const size_t n = mesh_.vertex_count();
  // First: the faces' corners then name the copies that stand for the split ones.
  if (opt_.split_vertices != SplitVertices::Keep) {
    welding_ = weld_split_vertices(mesh_.triangles, mesh_.positions, &workers_);
    rep_.welded_vertices = welding_.welded;
  }
  auto standing = [&](uint32_t v) { return welding_.rep.empty() ? v : welding_.rep[v]; };
  // Per face slot, its input face: for the set-up only (the run reads it off order_.face_old
  // and kept_faces_).
  UninitVector<uint32_t> face_source;
  rep_.dropped_degenerate_faces =
      drop_repeated_corner_faces(mesh_.triangles, face_source, &workers_);
  // Inside, vertices and faces go in spatial order (compact() restores the input's).
  order_ = spatial_order(mesh_.positions, mesh_.triangles, &workers_);
  {
    UninitVector<uint32_t> source(face_source.size());
    for_each_block(&workers_, source.size(), 65536, [&](size_t begin, size_t end) {
      for (size_t f = begin; f < end; ++f)
        source[f] = face_source[order_.face_old[f]];
    });
    if (rep_.dropped_degenerate_faces) kept_faces_.swap(face_source);
    face_source.swap(source);
  }
  flags_.assign(n, uint8_t(RejectCount << kRefusedShift)); // refused by nothing yet
  if (opt_.locked) // a locked copy locks the copy standing for it
    for (uint32_t i = 0; i < n; ++i)
      if ((*opt_.locked)[i]) flags_[order_.vertex_new[standing(i)]] |= kFlagLocked;
  // A NaN/inf position poisons every plane it takes part in: lock it and its neighbours.
  const auto& t = mesh_.triangles;
  for (size_t v = 0; v < n; ++v)
    if (!is_finite(eval_.position(static_cast<uint32_t>(v)))) ++rep_.nonfinite_vertices;
  if (rep_.nonfinite_vertices)
    for (size_t i = 0; i < t.size(); i += 3)
      if (!is_finite(eval_.position(t[i])) || !is_finite(eval_.position(t[i + 1])) ||
          !is_finite(eval_.position(t[i + 2])))
        flags_[t[i]] |= kFlagLocked, flags_[t[i + 1]] |= kFlagLocked,
            flags_[t[i + 2]] |= kFlagLocked;

  topo_.build(t, n, &workers_);
  // Before anything reads a fan: faces written in random orientation make every vertex look
  // non-manifold.
  std::vector<uint8_t> reversed;
  rep_.reoriented_faces =
      orient_coherently(mesh_.triangles, topo_, face_source.data(), reversed, &workers_);
  TurnedByWelding turned;
  if (welding_.same_way) {
    // Pieces of split vertices written in different orientations agree for the run only: the
    // output gives each face the orientation of the input faces it stands for.
    std::vector<uint32_t> apart(t.size());
    for (size_t f = 0; f < face_source.size(); ++f)
      for (int c = 0; c < 3; ++c)
        apart[3 * f + c] = order_.vertex_new[welding_.corners[3 * size_t(face_source[f]) + c]];
    turned = turned_by_welding(t, topo_, reversed, std::move(apart), face_source.data(), &workers_);
    if (!turned.faces.empty()) {
      turned_.assign(face_source.size() + rep_.dropped_degenerate_faces, 0); // by input face
      rep_.reoriented_faces = 0; // those the output holds reversed
      for (size_t f = 0; f < face_source.size(); ++f) {
        turned_[face_source[f]] = turned.faces[f];
        rep_.reoriented_faces += (!reversed.empty() && reversed[f]) != turned.faces[f];
      }
    }
  }
  {
    Options renumbered = opt_;
    std::vector<uint32_t> pairs;
    if (opt_.constrained_edges) {
      pairs = *opt_.constrained_edges;
      for (uint32_t& v : pairs)
        if (v < n) v = order_.vertex_new[standing(v)]; // out-of-range pairs stay ignored
    }
    if (opt_.split_vertices == SplitVertices::Seam) // each side keeps its copies
      for (uint32_t v : welding_.seams)
        pairs.push_back(order_.vertex_new[v]);
    // No face across two orientations (already in the run's numbering).
    pairs.insert(pairs.end(), turned.edges.begin(), turned.edges.end());
    if (!pairs.empty()) renumbered.constrained_edges = &pairs;
    rep_.constrained_edges = constraints_.build(renumbered, mesh_.positions.data(), t, topo_, n);
  }
  if (opt_.corner_sources || !welding_.rep.empty()) { // welded: output corners take copies
    corner_source_.resize(t.size());
    for (size_t f = 0; f < face_source.size(); ++f)
      for (int c = 0; c < 3; ++c)
        corner_source_[3 * f + c] =
            3 * face_source[f] + (reversed.empty() || !reversed[f] || !c ? c : 3 - c);
  }
  UninitVector<uint32_t>().swap(face_source);
  UninitVector<uint8_t> kinds;
  UninitVector<FirstPrice> first;
  first_prices(kinds, first);
  // Several fans at one vertex (fan_split.h): a copy a fan, and the set-up made again in the
  // new numbering (on such meshes only).
  if (split_fans_apart(kinds)) first_prices(kinds, first);
  // Its corner in the input (the first), for the per-corner data of the faces it then joins.
  if (!corner_source_.empty()) {
    slide_.corner.assign(slide_.target.size(), kNone); // split fans: more vertices than n
    for (size_t i = 0; i < t.size(); ++i)
      if (slide_.target[t[i]] && slide_.corner[t[i]] == kNone)
        slide_.corner[t[i]] = corner_source_[i];
  }
  // Counted in blocks on the workers (each vertex writes only its own flags and price), the
  // blocks' counts added in order.
  struct Counts {
    size_t unreferenced = 0, boundary = 0, nonmanifold = 0, high_valence = 0, locked = 0,
           constrained = 0, vertices = 0;
    ptrdiff_t flip_refused = 0;
    std::array<size_t, RejectCount> rejected{};
  };
  constexpr size_t kCountBlock = 65536;
  std::vector<Counts> counts((kinds.size() + kCountBlock - 1) / kCountBlock);
  for_each_block(&workers_, kinds.size(), kCountBlock, [&](size_t begin, size_t end) {
    Counts& c = counts[begin / kCountBlock];
    for (size_t i = begin; i < end; ++i) {
      const uint32_t v = uint32_t(i);
      const VertexKind kind = static_cast<VertexKind>(kinds[v] & ~kKeptOnConstraints);
      switch (kind) {
      case VertexKind::Isolated: ++c.unreferenced; continue;
      case VertexKind::Boundary:
      case VertexKind::Corner: c.boundary += !removable(kind); break;
      case VertexKind::NonManifold: ++c.nonmanifold; break;
      case VertexKind::HighValence: ++c.high_valence; break;
      case VertexKind::Interior: break;
      }
      ++c.vertices;
      if (flags_[v] & kFlagTwin) {
        ++c.boundary;
        continue;
      }
      if (flags_[v] & kFlagLocked) {
        ++c.locked;
        continue;
      }
      if (!removable(kind)) continue;
      if (kinds[v] & kKeptOnConstraints) {
        ++c.constrained;
        continue;
      }
      const FirstPrice& p = first[v]; // written: v was priced
      if (p.planned) {                // note(), its counts kept apart
        c.flip_refused += refuse(v, p.why);
        if (p.why != RejectCount) ++c.rejected[p.why];
      }
      priority_[v] = static_cast<float>(p.priority);
    }
  });
  for (const Counts& c : counts) {
    rep_.unreferenced_vertices += c.unreferenced;
    rep_.kept_boundary += c.boundary;
    rep_.kept_nonmanifold += c.nonmanifold;
    rep_.kept_high_valence += c.high_valence;
    rep_.kept_locked += c.locked;
    rep_.kept_constrained += c.constrained;
    vertices_ += c.vertices;
    flip_refused_ = size_t(ptrdiff_t(flip_refused_) + c.flip_refused);
    for (int r = 0; r < RejectCount; ++r)
      rep_.rejected[r] += c.rejected[r];
  }
  rep_.unreferenced_vertices -= welding_.welded; // the welded copies: no face names them now
  // The input's faces, for the relaxed passes' fold-over check (last_resort.cpp), copied once
  // the first prices' scratch is gone (so that the copy does not raise the peak).
  UninitVector<FirstPrice>().swap(first);
  UninitVector<uint8_t>().swap(kinds);
  // Not when the target is asked at any cost (max_price_jump 0): the eased passes then fold
  // where nothing else reaches it, as before. The hierarchy is built when a plan first asks.
  if (opt_.tuning.against_input && opt_.relax_to_reach_target && opt_.max_price_jump > 0) {
    const TurnedSlots turned = turned_slots();
    std::vector<uint8_t> by_slot;
    if (turned.any()) {
      by_slot.resize(t.size() / 3);
      for (size_t f = 0; f < by_slot.size(); ++f)
        by_slot[f] = turned(uint32_t(f));
    }
    input_.keep(t, std::move(by_slot), &workers_);
    planner_.set_input(&input_, turned);
  }
}

} // namespace vrs
