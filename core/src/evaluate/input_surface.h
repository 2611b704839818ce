// The input surface as it was read, for questions about the input itself ("which input face
// is nearest this point?") after the mesh's own faces have drifted from it. A bounding-volume
// hierarchy with no pointers: the faces reordered by median splits, leaves of kLeaf
// consecutive faces, each level's node i the box of nodes 2i and 2i + 1 below. (Leaves taken
// straight from the Morton order setup gives the faces made far looser boxes, slower to
// search.)
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <utility>
#include <vector>

#include "base/positions.h"
#include "base/uninitialized.h"
#include "base/workers.h"
#include "fill/triangulation.h"

namespace vrs {

// Which of the run's faces it holds reversed from how they were written (InputSurface::keep's
// `turned`), by face slot: as the output writes them back (output.cpp), by the input face of
// a face's first corner.
struct TurnedSlots {
  const std::vector<uint8_t>* by_input_face = nullptr; // nullptr or empty: none
  const std::vector<uint32_t>* corner_source = nullptr;
  bool any() const {
    return by_input_face && !by_input_face->empty() && corner_source && !corner_source->empty();
  }
  bool operator()(uint32_t slot) const {
    return (*by_input_face)[(*corner_source)[3 * size_t(slot)] / 3];
  }
  // InputSurface::folds's `turned` for `count` new triangles, triangle t standing where face
  // slot `slot_of(t)` did.
  template <class SlotOf> uint64_t triangles(int count, SlotOf slot_of) const {
    uint64_t turned = 0;
    if (any())
      for (int t = 0; t < count; ++t)
        turned |= uint64_t((*this)(slot_of(t))) << t;
    return turned;
  }
};

class InputSurface {
 public:
  // Copies the faces (the live array is rewritten as the run goes). Cheap: the hierarchy is
  // built only when asked for (build), and most runs never ask.
  // `turned` (a byte a face, or empty): the faces the run holds reversed from how they were
  // written (orientation.h, turned_by_welding). A fold is then judged as written, as the
  // output gives the faces back: a new triangle of the other orientation than the input face
  // nearest it faces away where the run sees them agree (a slope across a staircase of
  // pieces written in different orientations, as CGAL's boeing).
  void keep(const std::vector<uint32_t>& tris, std::vector<uint8_t> turned = {},
            Workers* workers = nullptr) {
    tris_.resize(tris.size()); // copied block by block on the workers
    for_each_block(workers, tris.size(), 3 * 65536, [&](size_t begin, size_t end) {
      std::copy(tris.begin() + begin, tris.begin() + end, tris_.begin() + begin);
    });
    turned_ = std::move(turned);
  }
  // Builds the hierarchy over the faces kept; faces without area are left out (they have no
  // side). Once, by the first caller (folds() calls it, from any thread); nothing to do
  // afterwards. Runs on smooth meshes never ask, and never pay for it (its time, and boxes of 6
  // bytes a face, 10 more while it is set up). False: not built, as a Deferral on
  // this thread asked.
  bool build(const Positions& eval) const;
  // The same, its splits spread over the workers (from outside their loops).
  void build_on(const Positions& eval, Workers* workers) const;
  bool kept() const { return !tris_.empty(); }
  // Whether the hierarchy was built.
  bool built() const { return done_.load(std::memory_order_acquire) && !levels_.empty(); }

  // While one lives on a thread, a question there that would build the hierarchy builds
  // nothing: it answers "folds" and wanted() turns true. A loop on the workers plans under
  // one, so that no thread builds it alone while the others wait (the build takes ten times
  // a part's round); the caller throws away what it planned, builds on all the workers, and
  // plans again.
  class Deferral {
   public:
    Deferral();
    ~Deferral();
    Deferral(const Deferral&) = delete;
    Deferral& operator=(const Deferral&) = delete;
    bool wanted() const { return wanted_; }

   private:
    friend class InputSurface;
    bool wanted_ = false;
    Deferral* outer_;
  };
  // The faces kept (3 indices a face; after build(), in the hierarchy's order).
  const UninitVector<uint32_t>& faces() const { return tris_; }

  // The input face nearest x: its unit normal in `normal` and the squared distance in `d2`.
  // False when there is none (no face with area).
  // `hint` (in and out): a face near x to start from (the last answer for a point close by:
  // its distance bounds the search at once), then the face found;
  // kNoFace for none. Ties may then answer another face as near: folds() asks ties again.
  static constexpr size_t kNoFace = ~size_t(0);
  // The squared distance within which another face counts as as near as one at d2 from x: a
  // slack relative to the distance and to x's magnitude (a denormal-scale cube's ties, the
  // fuzzer's), for every fold question that asks ties again.
  static double tie_reach2(double d2, Vec3 x) { return d2 * (1 + 1e-6) + 1e-24 * dot(x, x); }
  // A point agrees with the input where a face as near as the nearest (within tie_reach2)
  // turns less than 60 degrees from the triangle (this dot product of unit normals), or where
  // those faces' normals summed turn less than 90 degrees from it: the same answer whichever
  // of them a search meets first. The benchmark takes one of the nearest: "any of them turns
  // less than 90 degrees" let fins stand across a ridge, near 90 degrees from both flanks; a
  // face along one side of a crease agrees.
  static constexpr double kAgreeAlone = 0.5;
  // That question, one tied face at a time, for a triangle facing n (of length `length`).
  class TieVote {
   public:
    TieVote(Vec3 n, double length) : n_(n), alone_(kAgreeAlone * length) {}
    // Whether a face of unit normal m agrees on its own (then the ties do, whatever else).
    bool alone(Vec3 m) const { return dot(m, n_) > alone_; }
    void add(Vec3 m) { sum_ = sum_ + m; }
    bool summed() const { return dot(sum_, n_) > 0; }

   private:
    Vec3 n_, sum_{0, 0, 0};
    double alone_;
  };
  // `normal` as written when the asking triangle is `turned` (keep()).
  bool nearest(Vec3 x, const Positions& eval, double& d2, Vec3& normal, size_t* hint = nullptr,
               bool turned = false) const;

  // Whether some new triangle of the patch turns more than 90 degrees from the input face
  // nearest one of its sample points (its centroid and halfway from there to each corner; on
  // a triangle over more input faces, about a point every two faces covered, up to 144):
  // a fold-over as the benchmark measures one, against the input itself. Where several input
  // faces are nearest (an edge, a crease), as kAgreeAlone says.
  // Triangles covering fewer than `min_covers` input faces (by area) are not asked, and the
  // grid's side is at most `max_side` (2: the four points).
  // `turned`: bit t set for each new triangle the run holds reversed from how it will be
  // written (keep()'s `turned`; 0 for none).
  bool folds(const Patch& patch, const Positions& eval, double min_covers = 0,
             int max_side = kGridMax, uint64_t turned = 0) const;
  // The area of the patch's new triangles of at least `min_area` that turns more than 90
  // degrees from the input face nearest it, each point of a grid like folds()'s standing for
  // its sub-triangle; counted until it passes `budget` (then a value past it).
  double folded_area(const Patch& patch, const Positions& eval, double min_area, double budget,
                     uint64_t turned = 0) const;
  static constexpr int kGridMax = 12; // the sample grid's cells a side at most
  // The grid's cells a side (each_grid_point's L) for a triangle covering `covers` input
  // faces (by area): 2 to max_side, growing with the square root.
  static int grid_side(double covers, int max_side = kGridMax);

  // The centroids' range [lo, hi] (the whole range, given) cut down to the bulk of the faces:
  // past kBulkSpan interquartile widths (the widest axis's) from the middle half. The
  // hierarchy's 16-bit centroids are scaled to it and clamped: a few vertices at 1e38 (the
  // fuzzer) stretched the scale so far that every other face fell in one step, and the median
  // splits cut the bulk at random (leaves spanning the mesh, most opened by every question:
  // fuzz/open/'s slow case). An ordinary mesh's whole range lies within its
  // bulk's: nothing changes.
  static void clamp_to_bulk(const std::function<Vec3(size_t)>& centroid, size_t faces, double* lo,
                            double* hi, Workers* workers = nullptr);

 private:
  static constexpr int kLeaf = 4;
  static constexpr double kGridPerSide = 0.75;  // grid cells along a side per sqrt(faces covered)
  static constexpr double kCellsPerBudget = 4;  // folded_area's grid: cells per budget's area
  static constexpr double kBulkSpan = 16;       // see clamp_to_bulk
  static constexpr double kCutAt = 4;           // cut_long_faces: box's middle extent / height
  static constexpr int kMostPieces = 32;        // a face's pieces at most
  static constexpr size_t kMostItems = 2;       // items a face at most, all faces together,
  static constexpr size_t kItemsAnyway = 65536; // besides these
  static constexpr size_t kCutShare = 64;       // cut when one face in this many is a sliver
  struct Box {
    float lo[3], hi[3];
  };
  struct Piece {
    uint32_t face;
    Box box;
  };
  double box_distance2(const Box& b, Vec3 x) const;
  // A leaf's box from its faces' corners: not stored, as the leaves' boxes were half the
  // hierarchy's memory (6 bytes an input face) and the peak of runs that build it.
  Box leaf_box(size_t leaf, const Positions& eval) const;
  Box node_box(size_t level, size_t i, const Positions& eval) const {
    return level ? levels_[level][i] : leaf_box(i, eval);
  }
  size_t node_count(size_t level) const { return level ? levels_[level].size() : leaves_; }
  // The items [first, second) under a leaf (level 0) or a node over leaves (level 1): the
  // searches read a node over leaves at once, as its leaves' boxes would read the same corners.
  std::pair<size_t, size_t> items_under(size_t level, size_t i) const {
    const size_t span = (level ? 2 : 1) * size_t(kLeaf);
    return {i * span, std::min(item_count(), (i + 1) * span)};
  }
  // The hierarchy's items: the faces themselves, or (items_ not empty) the faces with the long
  // slivers lying across the axes cut into pieces (cut_long_faces).
  size_t item_count() const { return items_.empty() ? tris_.size() / 3 : items_.size(); }
  size_t item_face(size_t i) const {
    if (items_.empty()) return i;
    const uint32_t item = items_[i];
    return item < tris_.size() / 3 ? item : pieces_[item - tris_.size() / 3].face;
  }
  const Box* piece_box(size_t i) const { // a piece's box; nullptr for a whole face
    if (items_.empty() || items_[i] < tris_.size() / 3) return nullptr;
    return &pieces_[items_[i] - tris_.size() / 3].box;
  }
  // An item's centroid to 16 bits an axis and its index, side by side: the splits read the
  // keys in place (through an index array they missed the cache). 10 bytes, what the keys and
  // the index array took apart.
  struct SplitItem {
    uint16_t key[3];
    uint16_t low, high; // the index, in halves: no padding
    uint32_t index() const { return uint32_t(low) | uint32_t(high) << 16; }
    void set_index(uint32_t i) { low = uint16_t(i), high = uint16_t(i >> 16); }
  };
  // The order of `count` items for the leaves, a median split of their centroids at each level.
  static UninitVector<SplitItem>
  split_order(size_t count, const std::function<Vec3(size_t)>& centroid, Workers* workers);
  void order_faces(const Positions& eval, Workers* workers) const; // tris_ in split_order
  // A sliver lying across the axes (a diagonal cylinder's faces from end to end) has a box
  // spanning much of the mesh, opened by every question near any of it: on such a cylinder
  // every question read every face. Where they are
  // not rare, such faces enter the hierarchy cut across their length into pieces, each with
  // the box of its part; a face's nearest point lies in one of its pieces' boxes, so every
  // search answers as before.
  void cut_long_faces(const Positions& eval, Workers* workers) const;
  // Whether the faces within sqrt(r2) of x agree with a triangle facing n (kAgreeAlone).
  // `turned`: the asking triangle's orientation (keep()), in these three.
  bool ties_agree(Vec3 x, double r2, Vec3 n, const Positions& eval, bool turned) const;
  // Whether a triangle facing n turns from the input at its point x, ties answered as
  // kAgreeAlone says; `hint` as nearest()'s.
  bool turned_at(Vec3 x, Vec3 n, const Positions& eval, size_t& hint, bool turned) const;
  // Face f's unit normal, reversed when f and the asking triangle are held in different
  // orientations: the two compared as written.
  Vec3 face_normal(size_t f, const Positions& eval, bool turned) const;

  // Writes the mutable members below: const because the hierarchy is built on first use,
  // under build_once_, before any reader sees them.
  void build_now(const Positions& eval, Workers* workers) const;
  mutable std::once_flag build_once_;
  mutable std::atomic<bool> done_{false}; // build_now has run
  mutable uint64_t id_ = 0;               // this build's, unique in the process (TriangleAnswers)
  mutable UninitVector<uint32_t> tris_;   // 3 a face, faces with area only
  mutable std::vector<uint8_t> turned_;   // a byte a face of tris_, or empty (keep())
  mutable double mean_area_ = 0;          // of the input's faces with area
  mutable UninitVector<uint32_t> items_;  // a face (< faces), or faces + its index in pieces_
  mutable std::vector<Piece> pieces_;
  mutable size_t leaves_ = 0;
  // levels_[l]: the boxes of level l, each over two of the level below (levels_[0] is empty:
  // the leaves', made when read); the last: the root.
  mutable std::vector<std::vector<Box>> levels_;
};

} // namespace vrs
