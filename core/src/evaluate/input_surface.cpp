#include "evaluate/input_surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "base/distance.h"
#include "evaluate/triangle_answers.h"

namespace vrs {

void InputSurface::clamp_to_bulk(const std::function<Vec3(size_t)>& centroid, size_t faces,
                                 double* lo, double* hi, Workers* workers) {
  if (faces < 8) return;
  UninitVector<float> x(faces); // before the centroids' 6 bytes a face: not a new peak
  double q1[3], q3[3], width = 0;
  for (int a = 0; a < 3; ++a) {
    for_each_block(workers, faces, 65536, [&](size_t begin, size_t end) {
      for (size_t f = begin; f < end; ++f) {
        const Vec3 c = centroid(f);
        x[f] = float(a == 0 ? c.x : a == 1 ? c.y : c.z);
      }
    });
    std::nth_element(x.begin(), x.begin() + faces / 4, x.end());
    q1[a] = x[faces / 4];
    std::nth_element(x.begin() + faces / 4, x.begin() + 3 * faces / 4, x.end());
    q3[a] = x[3 * faces / 4];
    width = std::max(width, q3[a] - q1[a]);
  }
  if (!(width > 0) || !std::isfinite(width)) return;
  for (int a = 0; a < 3; ++a)
    lo[a] = std::max(lo[a], q1[a] - kBulkSpan * width),
    hi[a] = std::min(hi[a], q3[a] + kBulkSpan * width);
}

UninitVector<InputSurface::SplitItem>
InputSurface::split_order(size_t count, const std::function<Vec3(size_t)>& centroid,
                          Workers* workers) {
  // Top-down median splits on the centroids' widest axis, into the implicit layout the levels
  // read: a node of 2^l leaf slots gives its left child exactly 2^(l-1) * kLeaf items (or all
  // it has), so node i of a level has children 2i and 2i + 1 below.
  // The centroids to 16 bits an axis, one scale for all three (6 bytes a face where floats
  // took 12, and the faces permuted in place: this set-up was the run's peak, 7 MB above the
  // hierarchy it leaves at 300 k faces). Any split gives the same answers: folds() asks the
  // nearest face, then every face as near (ties), so the hierarchy decides only how fast.
  // Block by block on the workers; bounds and splits do not depend on the blocks.
  constexpr size_t kBlock = 65536;
  const size_t blocks = (count + kBlock - 1) / kBlock;
  std::vector<std::array<double, 6>> block_bounds(blocks);
  for_each_block(workers, count, kBlock, [&](size_t begin, size_t end) {
    auto& b = block_bounds[begin / kBlock];
    b = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
    for (size_t f = begin; f < end; ++f) {
      const Vec3 c = centroid(f);
      const double x[3] = {c.x, c.y, c.z};
      for (int a = 0; a < 3; ++a)
        b[a] = std::min(b[a], x[a]), b[3 + a] = std::max(b[3 + a], x[a]);
    }
  });
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (const auto& b : block_bounds)
    for (int a = 0; a < 3; ++a)
      lo[a] = std::min(lo[a], b[a]), hi[a] = std::max(hi[a], b[3 + a]);
  clamp_to_bulk(centroid, count, lo, hi, workers);
  const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  const double scale = extent > 0 && std::isfinite(extent) ? 65535.0 / extent : 0.0;
  UninitVector<SplitItem> order(count);
  for_each_block(workers, count, kBlock, [&](size_t begin, size_t end) {
    for (size_t f = begin; f < end; ++f) {
      const Vec3 c = centroid(f);
      const double x[3] = {c.x, c.y, c.z};
      for (int a = 0; a < 3; ++a)
        order[f].key[a] = uint16_t(std::min(65535.0, std::max(0.0, (x[a] - lo[a]) * scale + 0.5)));
      order[f].set_index(uint32_t(f));
    }
  });
  size_t slots = 1;
  while (slots * kLeaf < count)
    slots *= 2;
  struct Range {
    size_t begin, end, slots;
  };
  // A range's split, its halves to `out`: disjoint ranges split apart, so in any order.
  auto split = [&](const Range& r, std::vector<Range>& out) {
    if (r.slots <= 1 || r.end - r.begin <= size_t(kLeaf)) return;
    const size_t left = std::min(r.end, r.begin + r.slots / 2 * kLeaf);
    if (left < r.end) {
      uint16_t qlo[3] = {65535, 65535, 65535}, qhi[3] = {0, 0, 0};
      for (size_t i = r.begin; i < r.end; ++i)
        for (int a = 0; a < 3; ++a)
          qlo[a] = std::min(qlo[a], order[i].key[a]), qhi[a] = std::max(qhi[a], order[i].key[a]);
      int axis = 0;
      for (int a = 1; a < 3; ++a)
        if (qhi[a] - qlo[a] > qhi[axis] - qlo[axis]) axis = a;
      std::nth_element(
          order.begin() + r.begin, order.begin() + left, order.begin() + r.end,
          [&](const SplitItem& x, const SplitItem& y) { return x.key[axis] < y.key[axis]; });
      out.push_back({left, r.end, r.slots / 2});
    }
    out.push_back({r.begin, left, r.slots / 2});
  };
  // Level by level, each level's ranges on the workers, up to 32 ranges (two of the median's
  // halves for each of 16 threads: the same for any count, as the projection is made on one);
  // then each range's subtree on a worker.
  std::vector<Range> ranges{{0, count, slots}};
  std::vector<std::vector<Range>> halves;
  while (workers && !ranges.empty() && ranges.size() < 32) {
    halves.assign(ranges.size(), {});
    for_each_on(workers, ranges.size(), [&](size_t i) { split(ranges[i], halves[i]); });
    ranges.clear();
    for (const auto& h : halves)
      ranges.insert(ranges.end(), h.begin(), h.end());
  }
  for_each_on(workers, ranges.size(), [&](size_t i) {
    std::vector<Range> todo{ranges[i]};
    while (!todo.empty()) {
      const Range r = todo.back();
      todo.pop_back();
      split(r, todo);
    }
  });
  return order;
}

void InputSurface::order_faces(const Positions& eval, Workers* workers) const {
  const size_t faces = tris_.size() / 3;
  UninitVector<SplitItem> order = split_order(
      faces,
      [&](size_t f) {
        return (eval.position(tris_[3 * f]) + eval.position(tris_[3 * f + 1]) +
                eval.position(tris_[3 * f + 2])) *
               (1.0 / 3);
      },
      workers);
  // Face i takes face order[i], cycle by cycle; a placed entry is marked order[i] = i.
  for (size_t i = 0; i < faces; ++i) {
    if (order[i].index() == i) continue;
    const std::array<uint32_t, 3> first = {tris_[3 * i], tris_[3 * i + 1], tris_[3 * i + 2]};
    const uint8_t first_turned = turned_.empty() ? 0 : turned_[i];
    for (size_t j = i;;) {
      const size_t k = order[j].index();
      order[j].set_index(uint32_t(j));
      if (k == i) {
        std::copy(first.begin(), first.end(), &tris_[3 * j]);
        if (!turned_.empty()) turned_[j] = first_turned;
        break;
      }
      std::copy_n(&tris_[3 * k], 3, &tris_[3 * j]);
      if (!turned_.empty()) turned_[j] = turned_[k];
      j = k;
    }
  }
}

namespace {

// The box, rounded outwards to floats, of the part of triangle p between the planes where
// dot(x - p[0], u) is t0 and t1: its corners between them and its edges' crossings of them.
// Rounded outwards by a float step at least, so that it holds the exact part despite the
// crossings' rounding.
void part_box(const Vec3 p[3], Vec3 u, double t0, double t1, float lo[3], float hi[3]) {
  double t[3], dlo[3] = {INFINITY, INFINITY, INFINITY}, dhi[3] = {-INFINITY, -INFINITY, -INFINITY};
  auto add = [&](Vec3 x) {
    const double c[3] = {x.x, x.y, x.z};
    for (int a = 0; a < 3; ++a)
      dlo[a] = std::min(dlo[a], c[a]), dhi[a] = std::max(dhi[a], c[a]);
  };
  for (int k = 0; k < 3; ++k) {
    t[k] = dot(p[k] - p[0], u);
    if (t[k] >= t0 && t[k] <= t1) add(p[k]);
  }
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3;
    for (double plane : {t0, t1})
      if ((t[k] - plane) * (t[j] - plane) < 0)
        add(p[k] + (p[j] - p[k]) * ((plane - t[k]) / (t[j] - t[k])));
  }
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::nextafter(float(dlo[a]), -INFINITY);
    hi[a] = std::nextafter(float(dhi[a]), INFINITY);
  }
}

} // namespace

void InputSurface::cut_long_faces(const Positions& eval, Workers* workers) const {
  const size_t faces = tris_.size() / 3;
  // How many pieces each face is cut into: a face whose box's middle extent passes kCutAt
  // times its height (a sliver lying across the axes) into pieces about two heights across
  // that extent, up to kMostPieces.
  std::vector<uint8_t> pieces(faces, 1);
  constexpr size_t kBlock = 65536; // on the workers, the blocks' counts summed after
  std::vector<std::pair<size_t, size_t>> counted((faces + kBlock - 1) / kBlock);
  for_each_block(workers, faces, kBlock, [&](size_t begin, size_t end) {
    size_t cut = 0, total = 0;
    for (size_t f = begin; f < end; ++f) {
      const Vec3 p[3] = {eval.position(tris_[3 * f]), eval.position(tris_[3 * f + 1]),
                         eval.position(tris_[3 * f + 2])};
      double longest = 0;
      for (int k = 0; k < 3; ++k)
        longest = std::max(longest, length(p[(k + 1) % 3] - p[k]));
      const double height = length(cross(p[1] - p[0], p[2] - p[0])) / longest;
      auto extent = [](double a, double b, double c) {
        return std::max({a, b, c}) - std::min({a, b, c});
      };
      double e[3] = {extent(p[0].x, p[1].x, p[2].x), extent(p[0].y, p[1].y, p[2].y),
                     extent(p[0].z, p[1].z, p[2].z)};
      std::sort(e, e + 3);
      if (e[1] > kCutAt * height) {
        pieces[f] = uint8_t(std::min<double>(kMostPieces, std::ceil(e[1] / (2 * height))));
        ++cut;
      }
      total += pieces[f];
    }
    counted[begin / kBlock] = {cut, total};
  });
  size_t cut = 0, total = 0;
  for (const auto& [c, t] : counted)
    cut += c, total += t;
  // A few slivers in a large mesh: each question meets only those near it. Not worth an
  // item's 4 bytes a face.
  if (cut == 0 || cut < faces / kCutShare ||
      kMostItems * faces + kItemsAnyway > std::numeric_limits<uint32_t>::max())
    return;
  // Within the items' budget (4 bytes an item and 28 a piece), shared out by length.
  if (total > kMostItems * faces + kItemsAnyway) {
    const double keep = double(kMostItems * faces + kItemsAnyway - faces) / double(total - faces);
    total = 0;
    for (auto& k : pieces) {
      k = uint8_t(1 + std::floor((k - 1) * keep));
      total += k;
    }
  }
  items_.clear();
  items_.reserve(total);
  pieces_.clear();
  pieces_.reserve(total - (faces - cut));
  for (size_t f = 0; f < faces; ++f) {
    if (pieces[f] == 1) {
      items_.push_back(uint32_t(f));
      continue;
    }
    const Vec3 p[3] = {eval.position(tris_[3 * f]), eval.position(tris_[3 * f + 1]),
                       eval.position(tris_[3 * f + 2])};
    int longest = 0; // the edge p[longest] -> p[longest + 1]
    for (int k = 1; k < 3; ++k)
      if (length(p[(k + 1) % 3] - p[k]) > length(p[(longest + 1) % 3] - p[longest])) longest = k;
    const Vec3 u = normalized(p[(longest + 1) % 3] - p[longest]);
    double tmin = INFINITY, tmax = -INFINITY;
    for (const Vec3& x : p)
      tmin = std::min(tmin, dot(x - p[0], u)), tmax = std::max(tmax, dot(x - p[0], u));
    // Neighbouring parts overlap by a hair, and the ends reach past the corners: the crossings'
    // rounding leaves no point of the face outside every box.
    const double step = (tmax - tmin) / pieces[f], hair = 1e-6 * (tmax - tmin);
    for (int i = 0; i < pieces[f]; ++i) {
      Piece piece{uint32_t(f), {}};
      part_box(p, u, i == 0 ? -INFINITY : tmin + i * step - hair,
               i + 1 == pieces[f] ? INFINITY : tmin + (i + 1) * step + hair, piece.box.lo,
               piece.box.hi);
      items_.push_back(uint32_t(faces + pieces_.size()));
      pieces_.push_back(piece);
    }
  }
  const UninitVector<SplitItem> order = split_order(
      items_.size(),
      [&](size_t i) {
        const uint32_t item = items_[i];
        if (item < faces)
          return (eval.position(tris_[3 * item]) + eval.position(tris_[3 * item + 1]) +
                  eval.position(tris_[3 * item + 2])) *
                 (1.0 / 3);
        const Box& b = pieces_[item - faces].box;
        return Vec3{b.lo[0] + b.hi[0], b.lo[1] + b.hi[1], b.lo[2] + b.hi[2]} * 0.5;
      },
      workers);
  UninitVector<uint32_t> ordered(items_.size());
  for (size_t i = 0; i < items_.size(); ++i)
    ordered[i] = items_[order[i].index()];
  items_.swap(ordered);
}

namespace {
thread_local InputSurface::Deferral* deferring = nullptr; // the innermost on this thread
} // namespace

InputSurface::Deferral::Deferral() : outer_(deferring) {
  deferring = this;
}
InputSurface::Deferral::~Deferral() {
  deferring = outer_;
}

bool InputSurface::build(const Positions& eval) const {
  if (done_.load(std::memory_order_acquire)) return true;
  if (deferring) {
    deferring->wanted_ = true;
    return false;
  }
  std::call_once(build_once_, [&] { build_now(eval, nullptr); });
  return true;
}

void InputSurface::build_on(const Positions& eval, Workers* workers) const {
  std::call_once(build_once_, [&] { build_now(eval, workers); });
}

void InputSurface::build_now(const Positions& eval, Workers* workers) const {
  struct Done { // whichever way it returns
    std::atomic<bool>& flag;
    ~Done() { flag.store(true, std::memory_order_release); }
  } done{done_};
  static std::atomic<uint64_t> builds{0};
  id_ = ++builds;
  size_t kept = 0;
  for (size_t i = 0; i + 2 < tris_.size(); i += 3) {
    const Vec3 a = eval.position(tris_[i]), b = eval.position(tris_[i + 1]),
               c = eval.position(tris_[i + 2]);
    const double area2 = length(cross(b - a, c - a));
    if (is_finite(a) && is_finite(b) && is_finite(c) && area2 > 0) {
      if (!turned_.empty()) turned_[kept / 3] = turned_[i / 3];
      for (int k = 0; k < 3; ++k)
        tris_[kept++] = tris_[i + k];
      mean_area_ += 0.5 * area2;
    }
  }
  tris_.resize(kept);
  if (!turned_.empty()) turned_.resize(kept / 3);
  const size_t faces = tris_.size() / 3;
  if (faces == 0) return;
  mean_area_ /= double(faces);
  order_faces(eval, workers);
  cut_long_faces(eval, workers);
  leaves_ = (item_count() + kLeaf - 1) / kLeaf;
  levels_.emplace_back(); // the leaves' boxes: made from their faces when read (leaf_box)
  size_t below = leaves_;
  while (below > 1) {
    std::vector<Box> up((below + 1) / 2);
    for (size_t i = 0; i < up.size(); ++i) {
      up[i] = node_box(levels_.size() - 1, 2 * i, eval);
      if (2 * i + 1 < below) {
        const Box b = node_box(levels_.size() - 1, 2 * i + 1, eval);
        for (int a = 0; a < 3; ++a)
          up[i].lo[a] = std::min(up[i].lo[a], b.lo[a]),
          up[i].hi[a] = std::max(up[i].hi[a], b.hi[a]);
      }
    }
    below = up.size();
    levels_.push_back(std::move(up));
  }
}

InputSurface::Box InputSurface::leaf_box(size_t leaf, const Positions& eval) const {
  Box b;
  std::fill(b.lo, b.lo + 3, std::numeric_limits<float>::infinity());
  std::fill(b.hi, b.hi + 3, -std::numeric_limits<float>::infinity());
  const auto [first, last] = items_under(0, leaf);
  for (size_t i = first; i < last; ++i) {
    if (const Box* piece = piece_box(i)) {
      for (int a = 0; a < 3; ++a)
        b.lo[a] = std::min(b.lo[a], piece->lo[a]), b.hi[a] = std::max(b.hi[a], piece->hi[a]);
      continue;
    }
    const size_t f = item_face(i);
    for (int c = 0; c < 3; ++c) {
      const Vec3 p = eval.position(tris_[3 * f + c]);
      const float x[3] = {float(p.x), float(p.y), float(p.z)}; // positions are floats
      for (int a = 0; a < 3; ++a)
        b.lo[a] = std::min(b.lo[a], x[a]), b.hi[a] = std::max(b.hi[a], x[a]);
    }
  }
  return b;
}

double InputSurface::box_distance2(const Box& b, Vec3 x) const {
  const double p[3] = {x.x, x.y, x.z};
  double d2 = 0;
  for (int a = 0; a < 3; ++a) {
    const double d = p[a] < b.lo[a] ? b.lo[a] - p[a] : p[a] > b.hi[a] ? p[a] - b.hi[a] : 0.0;
    d2 += d * d;
  }
  return d2;
}

bool InputSurface::nearest(Vec3 x, const Positions& eval, double& d2, Vec3& normal, size_t* hint,
                           bool turned) const {
  if (levels_.empty()) return false;
  double best = std::numeric_limits<double>::infinity();
  size_t best_face = 0;
  if (hint && *hint != kNoFace) {
    best_face = *hint;
    best = point_triangle_distance2(x, eval.position(tris_[3 * best_face]),
                                    eval.position(tris_[3 * best_face + 1]),
                                    eval.position(tris_[3 * best_face + 2]));
  }
  // Depth-first, nearer child first; a node is (level, index) with its box's distance, measured
  // once. The depth is log2 of the leaves: 64 entries hold any mesh.
  struct Node {
    uint8_t level;
    uint32_t index;
    double d2;
  };
  std::array<Node, 64> stack;
  int top = 0;
  const uint8_t root = uint8_t(levels_.size() - 1);
  stack[top++] = {root, 0u, box_distance2(node_box(root, 0, eval), x)};
  while (top > 0) {
    const Node node = stack[--top];
    if (node.d2 >= best) continue;
    const uint8_t level = node.level;
    // A node over leaves has its faces read at once: making its leaves' boxes reads the same
    // corners (a leaf's box is not stored), so they would save no memory traffic, only add
    // work (a third of the time where every box ties, at 1e38: fuzz/open/).
    if (level <= 1) {
      const auto [first, last] = items_under(level, node.index);
      size_t last_face = kNoFace;
      for (size_t i = first; i < last; ++i) {
        const size_t f = item_face(i);
        // A piece is passed over when its face was just measured or its box is too far.
        if (const Box* piece = piece_box(i);
            piece && (f == last_face || box_distance2(*piece, x) >= best))
          continue;
        last_face = f;
        const double d = point_triangle_distance2(x, eval.position(tris_[3 * f]),
                                                  eval.position(tris_[3 * f + 1]),
                                                  eval.position(tris_[3 * f + 2]));
        if (d < best) best = d, best_face = f;
      }
      continue;
    }
    const uint8_t down = uint8_t(level - 1);
    const uint32_t a = 2 * node.index, b = 2 * node.index + 1;
    const double da = box_distance2(node_box(down, a, eval), x);
    if (b >= node_count(down)) {
      stack[top++] = {down, a, da};
      continue;
    }
    const double db = box_distance2(node_box(down, b, eval), x);
    // The nearer one is popped first.
    if (da <= db) {
      if (db < best) stack[top++] = {down, b, db};
      if (da < best) stack[top++] = {down, a, da};
    } else {
      if (da < best) stack[top++] = {down, a, da};
      if (db < best) stack[top++] = {down, b, db};
    }
  }
  if (!(best < std::numeric_limits<double>::infinity())) return false;
  if (hint) *hint = best_face;
  normal = face_normal(best_face, eval, turned);
  d2 = best;
  return true;
}

Vec3 InputSurface::face_normal(size_t f, const Positions& eval, bool turned) const {
  const Vec3 a = eval.position(tris_[3 * f]);
  const Vec3 n =
      normalized(cross(eval.position(tris_[3 * f + 1]) - a, eval.position(tris_[3 * f + 2]) - a));
  return !turned_.empty() && bool(turned_[f]) != turned ? n * -1.0 : n;
}

bool InputSurface::ties_agree(Vec3 x, double r2, Vec3 n, const Positions& eval, bool turned) const {
  TieVote vote(n, 1);
  // A long face is in the hierarchy in pieces (cut_long_faces): summed once.
  std::array<size_t, 16> seen;
  size_t seens = 0;
  std::array<std::pair<uint8_t, uint32_t>, 64> stack;
  int top = 0;
  stack[top++] = {uint8_t(levels_.size() - 1), 0u};
  while (top > 0) {
    const auto [level, index] = stack[--top];
    if (box_distance2(node_box(level, index, eval), x) > r2) continue;
    if (level <= 1) { // a node over leaves: its faces at once, as in nearest()
      const auto [first, last] = items_under(level, index);
      for (size_t i = first; i < last; ++i)
        if (const size_t f = item_face(i);
            point_triangle_distance2(x, eval.position(tris_[3 * f]),
                                     eval.position(tris_[3 * f + 1]),
                                     eval.position(tris_[3 * f + 2])) <= r2) {
          const Vec3 m = face_normal(f, eval, turned);
          if (vote.alone(m)) return true;
          if (std::find(seen.begin(), seen.begin() + seens, f) != seen.begin() + seens) continue;
          if (seens < seen.size()) seen[seens++] = f;
          vote.add(m);
        }
      continue;
    }
    const size_t below = node_count(level - 1);
    if (2 * index + 1 < below) stack[top++] = {uint8_t(level - 1), 2 * index + 1};
    stack[top++] = {uint8_t(level - 1), 2 * index};
  }
  return vote.summed();
}

bool InputSurface::turned_at(Vec3 x, Vec3 n, const Positions& eval, size_t& hint,
                             bool turned) const {
  double d2;
  Vec3 nearest_normal;
  if (!nearest(x, eval, d2, nearest_normal, &hint, turned) || TieVote(n, 1).alone(nearest_normal))
    return false;
  // Ties (an input edge or crease nearest): measured again with a hair of slack, relative
  // to the point's magnitude (an absolute one took in the whole of a cube 2e-41 wide).
  return !ties_agree(x, tie_reach2(d2, x), n, eval, turned);
}

int InputSurface::grid_side(double covers, int max_side) {
  // The centroids of the triangle's L x L sub-triangles: at L = 2 its centroid and halfway
  // from there to each corner (four points, not the centroid alone, which missed folds the
  // benchmark measures); L grows with the square root of how many input faces it covers, as
  // four points missed folds on small outputs. About a point every two faces covered, up to
  // 12 x 12 (not one every four, up to 6 x 6): folds of a tenth of a triangle between the
  // coarser grid's points are seen, in the same time.
  // Clamped before the conversion: a triangle 1e37 times the mean input face (the fuzzer)
  // made a side past any int.
  const double side = std::ceil(std::sqrt(covers) * kGridPerSide);
  const int most = std::max(2, std::min(kGridMax, max_side));
  return side >= most ? most : side > 2 ? int(side) : 2;
}

bool InputSurface::folds(const Patch& patch, const Positions& eval, double min_covers, int max_side,
                         uint64_t turned) const {
  if (!build(eval)) return true; // deferred: the caller plans again once it is built
  size_t hint = kNoFace;         // the sample points are asked in order, each near the one before
  TriangleAnswers& answers = TriangleAnswers::here();
  for (int t = 0; t < patch.count; ++t) {
    const auto& tri = patch.tri[t];
    const Vec3 a = patch.q[tri[0]], b = patch.q[tri[1]], c = patch.q[tri[2]];
    const Vec3 area_normal = cross(b - a, c - a);
    const Vec3 n = normalized(area_normal);
    const double covers = 0.5 * length(area_normal) / mean_area_;
    if (covers < min_covers) continue;
    TriangleAnswers::Question question;
    const bool kept = TriangleAnswers::question(a, b, c, id_, 2 + (turned >> t & 1), min_covers,
                                                max_side, question);
    double answer;
    if (!kept || !answers.find(question, answer)) {
      answer = each_grid_point(a, b, c, grid_side(covers, max_side), [&](Vec3 x) {
        return turned_at(x, n, eval, hint, turned >> t & 1);
      });
      if (kept) answers.store(question, answer);
    }
    if (answer) return true;
  }
  return false;
}

double InputSurface::folded_area(const Patch& patch, const Positions& eval, double min_area,
                                 double budget, uint64_t turned) const {
  if (!build(eval)) return std::numeric_limits<double>::infinity(); // deferred, as folds()
  size_t hint = kNoFace;
  TriangleAnswers& answers = TriangleAnswers::here();
  double folded = 0;
  const double inf = std::numeric_limits<double>::infinity();
  for (int t = 0; t < patch.count; ++t) {
    const auto& tri = patch.tri[t];
    const Vec3 a = patch.q[tri[0]], b = patch.q[tri[1]], c = patch.q[tri[2]];
    const Vec3 area_normal = cross(b - a, c - a);
    const double area = 0.5 * length(area_normal);
    if (!(area >= min_area)) continue;
    const Vec3 n = normalized(area_normal);
    // Cells of a quarter of the budget at most (the finest grid for no budget): a fold that
    // could pass it spans a few of them (the full grid: fewer folded runs for twice the small
    // runs' time; the grid of folds(), by faces covered: more).
    // Clamped before the conversion: a zero or denormal budget makes the side past any int.
    const double side =
        budget < inf ? std::ceil(std::sqrt(kCellsPerBudget * area / budget)) : kGridMax;
    const int L = side < kGridMax ? std::max(2, int(side)) : kGridMax;
    const double per_point = area / double(L * L); // L * L sub-triangles of equal area
    // The answer kept is the count of folded points, added one at a time as when asked.
    TriangleAnswers::Question question;
    const bool kept =
        TriangleAnswers::question(a, b, c, id_, 4 + (turned >> t & 1), min_area, budget, question);
    double points;
    if (kept && answers.find(question, points)) {
      for (; points > 0; --points)
        if ((folded += per_point) > budget) return folded;
      continue;
    }
    points = 0;
    if (each_grid_point(a, b, c, L, [&](Vec3 x) {
          if (turned_at(x, n, eval, hint, turned >> t & 1)) folded += per_point, ++points;
          return folded > budget;
        }))
      break; // not kept: the points after were not asked
    if (kept) answers.store(question, points);
  }
  return folded;
}

} // namespace vrs
