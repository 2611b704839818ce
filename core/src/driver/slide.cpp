// After the run (Options::slide): a kept interior vertex may give its place to a removed input
// vertex its faces carry, where its fan then stands nearer the input both ways and no face
// folds. The connectivity stays; the output's vertices stay input vertices, untouched. Each
// removal priced its last step only; this looks at the input itself, where error piled up.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "driver/simplifier.h"
#include "evaluate/local_error.h"
#include "evaluate/local_input.h"
#include "remove/vetoes.h"

namespace vrs {

namespace {

constexpr int kSlideTries = 16;   // places ranked by the input planes' quadric, vetoes asked
constexpr int kSlideMeasured = 3; // of those, the nearest the input's points measured both ways
constexpr size_t kSlideRound = 4096;
// Fans tried at most: those where the input stands farthest. Every fan of an output up to
// ~2 000 faces (the benchmark's tail keeps under 1 000); 2 000 fans gained little for twice
// the slide's time.
constexpr size_t kSlideFans = 1000;

// The fan of a ring around x: triangle i is (ring[i], ring[i + 1], x), in the ring's order.
void fan_patch(const Ring& ring, Vec3 x, const Evaluator& eval, Patch& out) {
  const int k = ring.verts;
  for (int i = 0; i < k; ++i) {
    out.q[i] = eval.position(ring.v[i]);
    out.tri[i] = {uint8_t(i), uint8_t((i + 1) % k), uint8_t(k)};
  }
  out.q[k] = x;
  out.count = k;
}

struct Plane {
  Vec3 n, p;
  double w;
};

// A fan's triangles' bounding spheres: a point's nearest triangle is sought from the last
// point's (the carried points come face by face), and a triangle whose sphere lies beyond the
// nearest so far is not measured, nor one whose plane does (a triangle is never nearer than its
// plane).
class FanBounds {
 public:
  explicit FanBounds(const Patch& patch) : patch_(patch) {
    for (int t = 0; t < patch.count; ++t) {
      const auto& tri = patch.tri[t];
      const Vec3 a = patch.q[tri[0]], b = patch.q[tri[1]], c = patch.q[tri[2]];
      centre_[t] = (a + b + c) * (1.0 / 3);
      corner_[t] = a;
      normal_[t] = normalized(cross(b - a, c - a));
      radius_[t] = std::sqrt(std::max({dot(a - centre_[t], a - centre_[t]),
                                       dot(b - centre_[t], b - centre_[t]),
                                       dot(c - centre_[t], c - centre_[t])})) *
                   (1 + 1e-12);
    }
  }
  // The squared distance from p to the fan: the least of its triangles' (a NaN one, from a
  // corner not finite, passed over as std::min does).
  double nearest2(Vec3 p) {
    double best = std::numeric_limits<double>::infinity(), s = best;
    const int first = hint_;
    for (int i = 0; i < patch_.count; ++i) {
      const int t = i == 0 ? first : i == first ? 0 : i; // the last point's nearest first
      const Vec3 d = p - centre_[t];
      const double reach = radius_[t] + s;
      if (dot(d, d) > reach * reach) continue; // no point of it is nearer than s
      const double h = dot(p - corner_[t], normal_[t]);
      if (h * h > best) continue; // its plane is already farther
      const double d2 = distance2(p, t);
      if (d2 < best) best = d2, s = std::sqrt(best), hint_ = t;
    }
    return best;
  }

 private:
  double distance2(Vec3 p, int t) const {
    const auto& tri = patch_.tri[t];
    return point_triangle_distance2(p, patch_.q[tri[0]], patch_.q[tri[1]], patch_.q[tri[2]]);
  }
  const Patch& patch_;
  std::array<Vec3, kMaxRing> centre_, corner_, normal_;
  std::array<double, kMaxRing> radius_;
  int hint_ = 0;
};

// A point a fan answers for: v or a point its faces carry, standing for a third of its input
// faces' area. Gathered once a fan, read by each place tried (not found again in the carried
// lists and the slots for every one).
struct SlidePoint {
  Vec3 x;
  double area;
  uint32_t id;
};

// Input to fan: the sum of the points' distances to it by their areas, but u's (u itself lies
// on it). Past `stop` the sum is no use to the caller: the rest is not measured (every term is
// positive, so what is returned still exceeds it). `farthest`: the largest squared distance.
double slide_in(const std::vector<SlidePoint>& points, uint32_t u, const Patch& patch,
                double* farthest = nullptr, double stop = std::numeric_limits<double>::infinity()) {
  double in = 0;
  FanBounds fan(patch);
  for (const SlidePoint& p : points) {
    if (in > stop) break;
    if (p.id == u) continue;
    const double d2 = fan.nearest2(p.x);
    in += p.area * std::sqrt(d2);
    if (farthest) *farthest = std::max(*farthest, d2);
  }
  return in;
}

} // namespace

bool Simplifier::slide_local(uint32_t v, const Ring& ring, LocalInput& in) const {
  std::vector<uint32_t>& faces = in.face;
  faces.clear();
  auto add = [&](uint32_t p) {
    const int k = slide_.slot(p);
    if (k >= 0)
      faces.insert(faces.end(), slide_.faces.begin() + slide_.first[k],
                   slide_.faces.begin() + slide_.first[k + 1]);
  };
  add(v);
  for (int i = 0; i < ring.verts; ++i)
    add(ring.v[i]);
  carried_.for_each(ring, add);
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  in.resize(faces.size());
  in.count = 0;
  in.mean_area = 0;
  const uint32_t* t = input_.faces().data();
  for (uint32_t face : faces) {
    const uint32_t* q = t + 3 * size_t(face);
    const Vec3 a = eval_.position(q[0]), b = eval_.position(q[1]), c = eval_.position(q[2]);
    const Vec3 n = cross(b - a, c - a);
    if (!(length(n) > 0)) continue; // no side
    const int k = in.count++;
    in.a[k] = a, in.b[k] = b, in.c[k] = c, in.n[k] = normalized(n);
    const Vec3 m = (a + b + c) * (1.0 / 3);
    in.cx[k] = m.x, in.cy[k] = m.y, in.cz[k] = m.z;
    in.mean_area += 0.5 * length(n);
    in.radius[k] = std::sqrt(std::max({dot(a - m, a - m), dot(b - m, b - m), dot(c - m, c - m)})) *
                   (1 + 1e-12);
  }
  if (in.count == 0) return false;
  in.mean_area /= in.count;
  return true;
}

uint32_t Simplifier::slide_choice(uint32_t v, const Ring& ring) const {
  const int k = ring.verts;
  Patch now;
  fan_patch(ring, eval_.position(v), eval_, now);
  std::array<Vec3, kMaxRing> old_n;
  for (int i = 0; i < k; ++i)
    old_n[i] = cross(now.q[(i + 1) % k] - now.q[i], now.q[k] - now.q[i]);
  thread_local std::vector<SlidePoint> points; // v first, then the carried points
  points.clear();
  auto gather = [&](uint32_t p) { points.push_back({eval_.position(p), slide_.area_of(p), p}); };
  gather(v);
  carried_.for_each(ring, gather);
  // The input's planes around (each carried point's, and v's: its input normal, weighted by
  // its area) rank the carried points as places for the fan's apex, cheaply, as a quadric
  // would; the few best are measured.
  std::array<Plane, 256> planes;
  int np = 0;
  for (const SlidePoint& p : points) {
    if (np == int(planes.size())) break;
    const float* c = &normals_[4 * size_t(p.id)];
    planes[np++] = {Vec3{c[0], c[1], c[2]}, p.x, p.area};
  }
  auto quadric = [&](Vec3 x) {
    double q = 0;
    for (int i = 0; i < np; ++i) {
      const double h = dot(planes[i].n, x - planes[i].p);
      q += planes[i].w * h * h;
    }
    return q;
  };
  std::array<std::pair<double, uint32_t>, kSlideTries> tries;
  int tried = 0;
  const TurnedSlots slots = turned_slots();
  const bool fan_turned = slots.any() && slots(ring.f[0]);
  for (auto p = points.begin() + 1; p != points.end(); ++p) {
    const uint32_t u = p->id;
    if ((flags_[u] & kFlagLocked) || !slide_.target[u]) continue;
    // Its per-corner data must come from a face wound as the fan's (an orientation border is
    // a constrained edge, but a point can be handed across one by a removal along it).
    if (slots.any() && bool(turned_[slide_.corner[u] / 3]) != fan_turned) continue;
    const std::pair<double, uint32_t> e{quadric(p->x), u};
    if (tried < kSlideTries) {
      tries[tried++] = e;
    } else {
      auto worst = std::max_element(tries.begin(), tries.end());
      if (e < *worst) *worst = e;
    }
  }
  if (tried == 0) return kNone;
  // The few nearest the input's points first (cheap), then the surface both ways. Each new
  // face answers to the vetoes a removal's fillings do, uneased (no sliver, its corners'
  // input normals agreeing, not turned over the face it replaces). Only the kSlideMeasured
  // nearest are used: once that many are known, a place is measured only until it passes
  // the farthest of them (the quadric's order first, so that bound tightens early; the same
  // choice).
  std::sort(tries.begin(), tries.begin() + tried);
  struct Near {
    double in;
    uint32_t u;
    uint8_t unsure; // veto_triangle's: corners unsure of the side the input faces
    double far;     // squared: the farthest of the input's points from the fan
    bool operator<(const Near& o) const { return in != o.in ? in < o.in : u < o.u; }
  };
  std::array<Near, kSlideTries> near;
  int nears = 0;
  Patch trial;
  FaceNormals replaced;
  for (int i = 0; i < k; ++i)
    replaced[i] = normalized(old_n[i]);
  RemovalLimits strict;
  strict.min_quality = limits_.min_quality;
  Ring apexed = ring;
  for (int ti = 0; ti < tried; ++ti) {
    const uint32_t u = tries[ti].second;
    fan_patch(ring, eval_.position(u), eval_, trial);
    apexed.v[k] = u;
    bool ok = true;
    uint8_t unsure = 0;
    for (int i = 0; i < k && ok; ++i)
      ok = veto_triangle(apexed, trial, trial.tri[i], replaced, normals_.data(), strict, false,
                         &unsure) == RejectCount;
    if (!ok) continue;
    double stop = std::numeric_limits<double>::infinity();
    if (nears >= kSlideMeasured) {
      std::nth_element(near.begin(), near.begin() + (kSlideMeasured - 1), near.begin() + nears);
      stop = near[kSlideMeasured - 1].in;
    }
    double far = 0;
    const double in = slide_in(points, u, trial, &far, stop);
    if (in <= stop) near[nears++] = {in, u, unsure, far}; // measured whole, so far is too
  }
  if (nears == 0) return kNone;
  std::sort(near.begin(), near.begin() + nears);
  thread_local LocalInput local; // grown once per thread, not per fan
  if (!slide_local(v, ring, local)) return kNone;
  bool folds;
  double far_now = 0; // squared: the farthest either way now, which no slide may pass
  const double in_now = slide_in(points, kNone, now, &far_now);
  double best = std::numeric_limits<double>::infinity();
  uint32_t chosen = kNone;
  uint8_t unsure = 0;
  for (int ni = 0; ni < std::min(nears, kSlideMeasured); ++ni) {
    const uint32_t u = near[ni].u;
    fan_patch(ring, eval_.position(u), eval_, trial);
    if (ni == 0)
      best = (in_now + measure_against(now, local, folds, std::numeric_limits<double>::infinity(),
                                       false, &far_now)) *
             (1 - 1e-3);
    if (!(near[ni].in < best)) break; // sorted: none after it either
    double far = 0;
    const double s =
        near[ni].in + measure_against(trial, local, folds, best - near[ni].in, false, &far);
    if (!(s < best) || folds) continue;
    // The mean nearer, not the max farther: unbounded, the max error grew.
    if (std::max(far, near[ni].far) > far_now) continue;
    best = s;
    chosen = u;
    unsure = near[ni].unsure;
  }
  if (chosen != kNone) {
    fan_patch(ring, eval_.position(chosen), eval_, trial);
    measure_against(trial, local, folds, std::numeric_limits<double>::infinity(), true);
    // And against the whole input where its corners are unsure (a thread's far flank is no
    // local face), as a removal's plan is: without it threaded parts folded more of their
    // area. Only where the run built its hierarchy (the CAD parts, where those
    // fans are): elsewhere refused, as building it would take 16 bytes a face at the peak.
    // The fan's triangle i stands where ring face i did.
    if (!folds && unsure)
      folds = !slide_.whole_input ||
              input_.folds(trial, eval_, 0, InputSurface::kGridMax,
                           slots.triangles(ring.faces, [&](int i) { return ring.f[i]; }));
    if (folds) chosen = kNone;
  }
  return chosen;
}

void Simplifier::slide() {
  if (!opt_.slide || opt_.mode != Mode::Surface3D || !carried_.active() || !input_.kept() ||
      !face_bound_.empty() || !fans_.empty() || slide_.target.size() != flags_.size())
    return;
  // The run's own per-vertex prices are done with: their memory goes to the slide's.
  UninitVector<float>().swap(priority_);
  UninitVector<float>().swap(fan_area_);
  UninitVector<uint8_t>().swap(chosen_);
  slide_.whole_input = input_.built(); // the run's, fixed: no slide builds it
  std::vector<uint32_t> pending = slide_gate();
  slide_index(pending);
  // Rounds: the pending vertices in order, each taken when its fan shares no vertex with one
  // taken before it in the round (the rest wait for the next); the round's choices made on
  // the workers against the same mesh, then written in order: the same output on any thread
  // count.
  uint32_t* tris = mesh_.triangles.data();
  struct Slot {
    uint32_t v, u;
    Ring ring;
  };
  std::vector<Slot> round;
  std::array<int, 2> seam;
  std::vector<uint32_t> later;
  while (!pending.empty()) {
    round.clear();
    later.clear();
    for (uint32_t v : pending) {
      if (round.size() >= kSlideRound || (flags_[v] & kFlagTaken)) {
        later.push_back(v);
        continue;
      }
      Ring ring;
      if (topo_.ring(v, tris, opt_.max_valence, ring) != VertexKind::Interior) continue;
      if (along(v, ring, seam) != Along::Free) continue;
      bool free = true;
      for (int i = 0; i < ring.verts && free; ++i)
        free = !(flags_[ring.v[i]] & kFlagTaken);
      if (!free) {
        later.push_back(v);
        continue;
      }
      flags_[v] |= kFlagTaken;
      for (int i = 0; i < ring.verts; ++i)
        flags_[ring.v[i]] |= kFlagTaken;
      round.push_back({v, kNone, ring});
    }
    // One fan a chunk (0.2-0.3 ms each): the last rounds hold few fans.
    workers_.for_each(
        round.size(), [&](size_t i) { round[i].u = slide_choice(round[i].v, round[i].ring); }, 1);
    for (Slot& s : round) {
      flags_[s.v] &= uint8_t(~kFlagTaken);
      for (int i = 0; i < s.ring.verts; ++i)
        flags_[s.ring.v[i]] &= uint8_t(~kFlagTaken);
      if (s.u != kNone) slide_commit(s.v, s.u, s.ring);
    }
    pending.swap(later);
  }
}

void Simplifier::slide_commit(uint32_t v, uint32_t u, const Ring& ring) {
  uint32_t* tris = mesh_.triangles.data();
  topo_.clear(u);
  for (int i = 0; i < ring.faces; ++i) {
    const uint32_t face = ring.f[i];
    for (int c = 0; c < 3; ++c)
      if (tris[3 * face + c] == v) {
        tris[3 * face + c] = u;
        if (!corner_source_.empty()) corner_source_[3 * size_t(face) + c] = slide_.corner[u];
      }
    topo_.add_face(u, face);
    order_.face_old[face] |= kRewrittenSlot;
  }
  topo_.clear(v);
  flags_[v] |= kFlagRemoved;
  flags_[u] &= uint8_t(~kFlagRemoved);
  Patch fan;
  fan_patch(ring, eval_.position(u), eval_, fan);
  carried_.slide(v, u, ring, fan, eval_);
  ++rep_.slid;
}

std::vector<uint32_t> Simplifier::slide_gate() {
  // The kept interior vertices on no constrained edge and no untouched half of a polygon,
  // scored by their carried points' distances to the faces carrying them (their nearest when
  // handed over); the kSlideFans highest, in vertex order.
  const uint32_t* tris = mesh_.triangles.data();
  std::vector<uint32_t> kept;
  for (size_t v = 0; v < flags_.size(); ++v)
    if (!(flags_[v] & (kFlagRemoved | kFlagLocked))) kept.push_back(uint32_t(v));
  std::vector<double> score(kept.size(), 0.0);
  workers_.for_each(
      kept.size(),
      [&](size_t i) {
        const uint32_t v = kept[i];
        Ring ring;
        std::array<int, 2> seam;
        if (topo_.ring(v, tris, opt_.max_valence, ring) != VertexKind::Interior ||
            along(v, ring, seam) != Along::Free)
          return;
        // A fan holding an untouched half of a polygon the caller writes back whole stays:
        // the polygon stays the user's (a quad's two triangles are written as one again).
        for (int f = 0; f < ring.faces; ++f)
          if (polygon_face(ring.f[f])) return;
        const Vec3 x = eval_.position(v);
        carried_.for_each_by_face(ring, [&](int f, uint32_t p) {
          const Vec3 a = eval_.position(ring.v[f]),
                     b = eval_.position(ring.v[(f + 1) % ring.verts]);
          score[i] += std::sqrt(point_triangle_distance2(eval_.position(p), a, b, x));
        });
      },
      256);
  std::vector<uint32_t> idx;
  for (size_t i = 0; i < kept.size(); ++i)
    if (score[i] > 0) idx.push_back(uint32_t(i));
  const size_t n = std::min(idx.size(), kSlideFans);
  std::nth_element(idx.begin(), idx.begin() + n, idx.end(), [&](uint32_t a, uint32_t b) {
    return score[a] != score[b] ? score[a] > score[b] : a < b;
  });
  idx.resize(n);
  std::sort(idx.begin(), idx.end());
  std::vector<uint32_t> fans;
  for (uint32_t i : idx)
    fans.push_back(kept[i]);
  return fans;
}

void Simplifier::slide_index(const std::vector<uint32_t>& fans) {
  // The vertices the tried fans may ask about (their apexes, rings and carried points): a slid
  // fan hands its points to its own faces, so these are all the later fans meet. Each gets a
  // slot, numbered in vertex order: its input faces (slide_local) and a third of their area
  // (slide_in: the input side of the error is an area integral, as the benchmark samples
  // it). Slots, not arrays over every vertex (the memory of those arrays showed at the peak).
  const uint32_t* tris = mesh_.triangles.data();
  std::vector<uint32_t> ids;
  for (uint32_t v : fans) {
    Ring ring;
    topo_.ring(v, tris, opt_.max_valence, ring);
    ids.push_back(v);
    ids.insert(ids.end(), ring.v.begin(), ring.v.begin() + ring.verts);
    carried_.for_each(ring, [&](uint32_t p) { ids.push_back(p); });
  }
  // The slots: a bit a vertex, numbered by rank (the bits set before it, counted a word at a
  // time): a slot found in two reads, not a search of a sorted list (that search was most of
  // the index's time at 1.2 M faces, all of it on one thread).
  const size_t words = (flags_.size() + 63) / 64;
  slide_.bits.assign(words, 0);
  for (uint32_t v : ids)
    slide_.bits[v >> 6] |= uint64_t(1) << (v & 63);
  std::vector<uint32_t>().swap(ids);
  slide_.rank.assign(words + 1, 0);
  for (size_t w = 0; w < words; ++w)
    slide_.rank[w + 1] = slide_.rank[w] + uint32_t(__builtin_popcountll(slide_.bits[w]));
  const size_t slots = slide_.rank.back();
  const uint32_t* f = input_.faces().data();
  const size_t faces = input_.faces().size() / 3;
  auto asked = [&](uint32_t v) { return slide_.slot(v) >= 0; };
  // The faces with an asked corner, found on the workers block by block (a pass over every
  // input face), then taken in order: each slot's faces and area as one thread would.
  constexpr size_t kBlock = 65536;
  std::vector<std::vector<uint32_t>> hits((faces + kBlock - 1) / kBlock);
  for_each_block(&workers_, faces, kBlock, [&](size_t begin, size_t end) {
    std::vector<uint32_t>& h = hits[begin / kBlock];
    for (size_t i = begin; i < end; ++i)
      if (asked(f[3 * i]) || asked(f[3 * i + 1]) || asked(f[3 * i + 2])) h.push_back(uint32_t(i));
  });
  auto each_corner = [&](auto&& fn) {
    for (const auto& h : hits)
      for (uint32_t face : h)
        for (int c = 0; c < 3; ++c) {
          const int k = slide_.slot(f[3 * size_t(face) + c]);
          if (k >= 0) fn(face, size_t(k));
        }
  };
  slide_.first.assign(slots + 1, 0);
  slide_.area.assign(slots, 0.0f);
  each_corner([&](uint32_t, size_t k) { ++slide_.first[k + 1]; });
  for (size_t k = 0; k < slots; ++k)
    slide_.first[k + 1] += slide_.first[k];
  slide_.faces.resize(slide_.first.back());
  std::vector<uint32_t> at(slide_.first.begin(), slide_.first.end() - 1);
  each_corner([&](uint32_t face, size_t k) { slide_.faces[at[k]++] = face; });
  // Each slot's area from its faces in their order (the sum one thread made), the slots on the
  // workers.
  for_each_block(&workers_, slots, 4096, [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k)
      for (uint32_t i = slide_.first[k]; i < slide_.first[k + 1]; ++i) {
        const uint32_t* q = f + 3 * size_t(slide_.faces[i]);
        const Vec3 a = eval_.position(q[0]), b = eval_.position(q[1]), d = eval_.position(q[2]);
        slide_.area[k] += float(length(cross(b - a, d - a)) / 6);
      }
  });
}

bool Simplifier::polygon_face(uint32_t f) const {
  const uint32_t old = order_.face_old[f];
  if (!opt_.polygon_faces || (old & kRewrittenSlot)) return false;
  return (*opt_.polygon_faces)[kept_faces_.empty() ? old : kept_faces_[old]] != 0;
}

} // namespace vrs
