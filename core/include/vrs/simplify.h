// vrsimplify — vertex-removal mesh simplification after Pivec & Domiter, "A General
// Simplification Algorithm" (extending Schroeder, Zarge & Lorensen 1992).
//
// One entry point: vrs::simplify(mesh, options) simplifies an indexed triangle mesh in place.
// Every output vertex is an input vertex (the report carries the old->new index map), so any
// per-vertex attribute the caller keeps beside the mesh survives exactly. The words used here
// (priority, veto, fill, eased passes, slide, ...) are defined in docs/glossary.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace vrs {

// Plain indexed triangle mesh: positions are xyz triples, triangles index triples into them.
// Triangles are oriented (counter-clockwise seen from outside); orientation is preserved.
struct Mesh {
  std::vector<float> positions;
  std::vector<uint32_t> triangles;

  size_t vertex_count() const { return positions.size() / 3; }
  size_t face_count() const { return triangles.size() / 3; }
};

// How a vertex's neighbourhood is flattened, both to evaluate the vertex and to re-triangulate
// its hole.
enum class Mode : uint8_t {
  Surface3D,  // average plane of the neighbours (the paper's 3D method)
  Terrain25D, // the XY plane: factor = mean |z - z_i| (the paper's 2.5D method, after Krivograd)
  Planar2D,   // the mesh's own plane, computed once (flat FEM-like meshes, any orientation)
};

// When to stop. Exactly one applies; Auto is the paper's own rule.
enum class TargetKind : uint8_t {
  Faces,     // stop at or below `faces` triangles
  Vertices,  // stop at or below `vertices` referenced vertices
  Ratio,     // stop at or below `ratio` * input triangles
  MaxFactor, // remove only vertices whose priority (see Priority) is <= `max_factor` (mesh units)
  Auto,      // stop when only the last interval of the hash table is left
};

struct Target {
  TargetKind kind = TargetKind::Ratio;
  size_t faces = 0;
  size_t vertices = 0;
  double ratio = 0.5;      // in [0, 1]
  double max_factor = 0.0; // >= 0, same unit as the positions
};

// The vertex selection structure. Intervals is the paper's hash table (Franc & Skala's bucket
// queue, O(1) per operation); Heap is an exact binary heap, O(log n), kept as the quality
// reference for the benchmark's ablation.
enum class QueueKind : uint8_t { Intervals, Heap };

// Mapping from evaluation factor to interval. Linear splits [0, f_max] evenly, as the paper;
// Logarithmic (the default) splits [f_max * 1e-6, f_max] evenly in log(f), 1.4 % apart at 1000
// intervals. Prices span decades (a CAD part's arcs cost a thousandth of its corners): linear
// intervals put them all in the first one, whose FIFO then strips one arc after another.
enum class IntervalMapping : uint8_t { Linear, Logarithmic };

// What the hash table sorts by. Factor is the paper's evaluation factor (the vertex's mean
// distance to its neighbours' average plane). LocalError plans the removal first and sorts by
// how far the re-triangulated patch stands from the surface it replaces (the larger of the
// vertex's distance to the new patch and the new triangles' and diagonals' distance to the old
// fan): costlier, and closer to what a surface-error measure sees.
enum class Priority : uint8_t { Factor, LocalError };

// How the hole a removed vertex leaves may be filled. Projection is the paper's only way: the
// ring projected on its average plane and triangulated there (fan or ear clipping by triangle
// shape). Best also tries the fan from each ring vertex (a half-edge collapse of the vertex
// onto that neighbour) and keeps, of the fillings no veto refuses, the one of least local
// error (see Priority::LocalError): lower error, and it goes on where projections fold.
enum class Fill : uint8_t { Projection, Best };

// Split vertices: copies of a vertex at one position, each side of a seam holding its own (a
// texture seam or a flat-shading crease written for rendering, a soup of faces each with its
// own three). Seam welds two border edges at the same two positions into one edge for the
// run and keeps each side's copies on output: the seam is a constrained edge (see
// constrained_edges), so the copies' own data (texture coordinates, normals) stay exact.
// Weld welds them the same way but without the seam: for copies that carry nothing of their
// own (positions only: the faces on either side may then take either copy). Keep leaves them
// apart as borders, as before (locked where the border is simplified, so no crack opens).
enum class SplitVertices : uint8_t { Keep, Seam, Weld };

// Progress: fraction of the planned work done, in [0, 1]. Return false to stop; the mesh is left
// valid (every removal is atomic).
using ProgressFn = std::function<bool(float fraction)>;

// The benchmark's switches: the paper's variants and the ways this implementation departs from
// them, kept so that bench/ablation.md can measure each. Users leave them as they are; the
// command line and the plugin still offer the paper's (queue, mapping, intervals, priority).
struct Tuning {
  QueueKind queue = QueueKind::Intervals;
  Priority priority = Priority::LocalError;
  Fill fill = Fill::Best;
  IntervalMapping mapping = IntervalMapping::Logarithmic;
  // Number of hash-table intervals, >= 2. The last one holds the vertices of highest factor;
  // TargetKind::Auto stops when only it is left, so more intervals simplify further.
  int intervals = 1000;
  // With Priority::LocalError, after a removal the neighbours still queued are only marked
  // stale and priced again when popped (pushed back if they no longer lead the queue); false
  // prices them all at once (the paper's way, and always with Priority::Factor, whose price
  // is cheap). Lazy halves the work or better; a neighbour whose price fell waits in place.
  bool lazy_reevaluation = true;
  // Lazy re-evaluation only on meshes of at least this many faces: smaller ones are priced at
  // once, where the whole run takes a fraction of a second and eager prices order it better
  // (less mean error, most at low targets, for about twice the time; CHANGELOG.md).
  // 0: lazy_reevaluation alone decides.
  size_t lazy_from_faces = 20000;
  // Fold-overs judged against the input, not only against faces that may already lean far
  // from it. With Priority::LocalError: each removed vertex is carried by the face nearest it,
  // and a removal is refused where a new triangle would face against the input's normal at a
  // vertex it carries (4 bytes a vertex and a face, and some time). Once the
  // vetoes are eased to reach a count target (Report::relaxed_removals), with either
  // priority, a new triangle must also not turn more than 90 degrees from the input face
  // nearest it (the input's faces are kept for that: 12 bytes a face), unless the target is
  // asked at any cost (max_price_jump 0).
  bool against_input = true;
  // Meshes of four parts or more are cut into parts of this many vertices along space, and
  // each part makes its cheapest removals on its own queue, all up to one shared price,
  // before the whole mesh's queue makes the last ones: every thread busy, the same output on
  // any number of them. 0: the whole mesh's queue from the start.
  int part_vertices = 16384;
};

struct Options {
  Target target;
  Mode mode = Mode::Surface3D;
  // Boundary vertices are kept by default (paper §2.2). When true, a boundary vertex may be
  // removed (factor: the larger of its distance to the line through its two boundary neighbours
  // and its average-plane factor); vertices of a single triangle are kept unless a count target
  // cannot be met otherwise (see Report::relaxed_removals). With Priority::Factor, corners,
  // where the outline turns by more than 30°, are kept the same way; the local error (the
  // default) prices them: the piece a corner's removal cuts off is its distance to the new
  // patch.
  bool simplify_boundary = false;
  // With a count target and boundary simplification off: when the kept border alone would
  // take more than a quarter of the faces asked for (any triangulation keeping B border
  // vertices of a surface of V vertices and F faces has at least 2B - 2V + F faces), the
  // border is simplified too (Report::boundary_simplified), as QECD does by default. Kept
  // whatever the target, such runs emptied the interior onto the border (a flat patch turned
  // into a tent fanned from one corner). False: the paper's rule.
  bool simplify_boundary_when_needed = true;
  SplitVertices split_vertices = SplitVertices::Seam;
  // A triangle of the projection filling may turn at most this far from the average plane's
  // normal: the projection check alone allows up to 90°, and nearly vertical triangles are
  // folds in waiting. Fans are held instead to the faces they replace (no fold-over).
  double max_normal_angle_deg = 80.0;
  // Vertices with more neighbours than this are kept: the removal's ear clipping is O(k^3)
  // and a hub that large is a feature (a cone apex, a fan centre), not noise.
  int max_valence = 32;
  // Optional per-vertex lock (nonzero = never removed), size vertex_count(): selections, tile
  // borders. Not owned.
  const std::vector<uint8_t>* locked = nullptr;
  // Optional per-face flag (nonzero = part of a polygon the caller writes back whole, as
  // MeshLab's faux edges join a quad's two triangles), size face_count(). The slide leaves a
  // face so flagged as the run left it, so that untouched polygons stay whole; elsewhere an
  // untouched face is a triangle like the others. Not owned.
  const std::vector<uint8_t>* polygon_faces = nullptr;
  // Constrained edges, as vertex index pairs (a0, b0, a1, b1, ...; either order): texture and
  // normal seams, material borders, any polyline the output must keep. A vertex on exactly two
  // constrained edges is removed only along them: both sides are re-triangulated apart and
  // the two edges become one (as an open border is simplified); a vertex on one, or on more
  // than two, is kept. Pairs that are not edges of the mesh are ignored. Not owned.
  const std::vector<uint32_t>* constrained_edges = nullptr;
  // Edges whose two faces' normals turn more than this many degrees apart are constrained too
  // (creases, as vtkDecimatePro's feature angle). 0 = off; in [0, 180].
  double feature_angle_deg = 0.0;
  // With Priority::LocalError and a count target: when the cheapest removal left would cost
  // more than this many times the dearest one made so far (and more than 1e-3 of the
  // bounding-box diagonal), the surface is about to change abruptly (a part dropped, a tunnel
  // pressed flat) rather than lose detail. Then a new triangle may first face away from the
  // input's normal at one of its three corners (until then at none); at the next such jump the
  // run stops short (StopReason::NoCandidates, stop_detail says so). Once eased, removals are
  // measured from the dearest one made before, against half this many times. 0: the target at
  // any cost (the eased passes may then fold over the input where nothing else reaches it).
  // Not with a finite max_error: the bound says how far a removal may go.
  double max_price_jump = 10.0;
  // After the run, in 3D mode: a kept interior vertex may give its place to a removed input
  // vertex its faces carried, where its faces then stand nearer the input and none folds (the
  // output's vertices stay input vertices, their attributes untouched; Report::slid), on the
  // 1 000 fans farthest from the input (every one of a small output). False: the run's faces.
  bool slide = true;
  // Threads to plan removals on (0: usable_cores()). The output is the same whatever the
  // number: independent removals are planned together, committed in queue order.
  int threads = 0;
  // A guaranteed error: no point of the output farther than this from the input surface, and
  // no point of the input farther than this from the output (symmetric Hausdorff distance),
  // in mesh units. 0 = off. With a count target too, whichever comes first stops the run.
  // Each face then carries a certified bound of its distance to the input it stands for
  // (Klein, Liebich & Strasser 1996), so removals whose patch would exceed it, or cannot be
  // certified, are refused (RejectBound); the run reports the bound it certifies in
  // Report::error_bound. +inf tracks and reports the bound without limiting anything. The
  // tracking costs a float a face and a polygon overlay per plan; it runs only when asked.
  double max_error = 0.0;
  // When the vetoes stop short of a count target, lift some of them to reach it (the last
  // resort, see Report::relaxed_removals). False: stop there instead (stop NoCandidates);
  // tiled runs do, since a later level over other tiles finishes the work.
  bool relax_to_reach_target = true;
  // Fill Report::corner_source, so that per-corner data (texture coordinates, normals, colors
  // stored per face corner) can follow the simplification. Costs 12 bytes a face.
  bool corner_sources = false;
  ProgressFn progress;
  Tuning tuning;
};

// Why a candidate removal was refused; the vertex stays and is retried after its ring changes.
enum Reject : uint8_t {
  RejectFold,       // ring does not project as a star around the vertex (the patch folds)
  RejectEdge,       // a new diagonal is already an edge of the mesh (would make it non-manifold)
  RejectTriangle,   // a new triangle already exists (would duplicate a face)
  RejectFlip,       // a new triangle turns more than max_normal_angle_deg from the plane, or
                    // faces away from the input surface at its corners
  RejectDegenerate, // a new triangle would be a sliver or have no area
  RejectFoldOver,   // a new triangle would face against a face it replaces (a fold-over)
  RejectBound,      // with Options::max_error: the patch would break the error bound, or cannot
                    // be certified (it does not project one-to-one with the faces it replaces)
  RejectCount
};
const char* reject_name(Reject r);

enum class StopReason : uint8_t {
  TargetReached, // the face / vertex / ratio target is met
  MaxFactor,     // no vertex left with factor <= max_factor
  LastInterval,  // only the last interval is left (Auto)
  NoCandidates,  // every remaining vertex is kept or was refused: the target cannot be reached
  Cancelled,     // the progress callback returned false
  InvalidInput,  // nothing was done, see Report::message
  ErrorBound,    // with Options::max_error: no removal left that keeps the bound (a target
                 // like the others: whichever of it and a count target comes first)
};
const char* stop_reason_name(StopReason r);

// What kept the run from its target (Report::stop_cause), for a program to act on: the price
// jump, the error bound, or else what keeps most of the vertices that remain. Report::stop_detail
// says the same in words, with every group's count.
enum class StopCause : uint8_t {
  None,        // nothing left stopped the run: its target was met (or it was cancelled)
  PriceJump,   // the cheapest removal left would change the surface abruptly (max_price_jump)
  ErrorBound,  // with Options::max_error: the bound stopped it (every removal left breaks it)
  Vetoes,      // every removal left folds, duplicates an edge or a face, or makes a sliver:
               // the floor of the input's topology (a genus, separate pieces) or its shape
  Boundary,    // on a boundary that is kept (simplify_boundary off), or outline corners
  Constrained, // where seams or creases end, meet or cross
  SplitSeam,   // on a seam of split vertices kept apart (split_vertices weld lifts it)
  Locked,      // locked by the caller
  NonFinite,   // a NaN or infinite coordinate, or next to one
  NonManifold, // non-manifold or inconsistently oriented neighbourhoods
  HighValence, // more neighbours than max_valence
  NoPlane,     // no usable plane (a degenerate neighbourhood)
};
const char* stop_cause_name(StopCause c);

struct Report {
  bool ok = false;     // false: invalid input or options, the mesh is unchanged
  std::string message; // the error, or warnings about the input (empty if none)
  StopReason stop = StopReason::InvalidInput;
  bool target_reached = false;

  size_t input_vertices = 0, input_faces = 0;
  // The count asked for (a ratio's face count, rounded), or 0 when the target is not one.
  size_t target_faces = 0, target_vertices = 0;
  size_t vertices = 0, faces = 0; // output (vertices: referenced ones, plus unreferenced inputs)
  size_t removed = 0;             // vertices removed
  size_t slid = 0;                // kept vertices that gave their place to a removed one
  // Wall time of the run, and the part of it spent in loops spread over the threads (the
  // rest ran on one thread whatever Options::threads: Amdahl's serial part).
  double seconds = 0, parallel_seconds = 0;
  size_t rejected[RejectCount] = {};
  size_t rejected_total() const;

  // What the input held that the simplifier had to work around.
  size_t dropped_degenerate_faces = 0; // faces with a repeated index (no area, no topology)
  size_t nonfinite_vertices = 0;       // NaN/inf coordinates: kept with their neighbours
  // Faces whose corners were reversed (second and third swapped) so that neighbours agree on
  // the orientation (in each connected piece, the one most of its faces had): a surface
  // written in random orientation is simplified as the surface it is. Pieces joined only by
  // welded split vertices (split_vertices) agree for the run and are written back in their
  // own orientation: not counted.
  size_t reoriented_faces = 0;
  size_t kept_boundary = 0, kept_nonmanifold = 0, kept_locked = 0, kept_high_valence = 0;
  // Vertices kept by the constrained edges (on one, or on more than two; or on the border).
  size_t kept_constrained = 0;
  size_t constrained_edges = 0;     // constrained edges of the input (given and by feature angle)
  size_t unreferenced_vertices = 0; // left untouched
  // Input vertices welded to another copy at their position for the run (split_vertices).
  size_t welded_vertices = 0;

  // Removals made once the input-normal veto was eased (a new triangle may face away from the
  // input's normal at one of its three corners: when most of what is left is refused by that
  // veto alone, or at a price jump, see max_price_jump) or lifted by the last resort: when
  // nothing else was left to remove and a count target was not met, a new triangle has to
  // face the input's side at one of its corners only,
  // single triangles (and the factor's outline corners) may go, and where every fan and the
  // projection of an interior vertex is refused, the ring's triangulation that stands nearest the
  // old fan, of those no veto refuses, is taken. It still may not fold over the faces it replaces.
  size_t relaxed_removals = 0;
  // Options::simplify_boundary_when_needed acted: the kept border alone needed more than a
  // quarter of the faces asked for, so border vertices were removed too.
  bool boundary_simplified = false;
  // When the target was not reached (stop == NoCandidates): what keeps the remaining
  // vertices, e.g. "remaining vertices: 64 on the boundary, kept (boundary simplification is
  // off); 2 refused by the vetoes (fold 1, edge_exists 1)".
  std::string stop_detail;
  StopCause stop_cause = StopCause::None;

  double max_removed_factor = 0.0; // largest priority (factor or local error) of a removed vertex
  // With Options::max_error: the certified bound of the symmetric Hausdorff distance between
  // the output and the input (mesh units; 0 when nothing was removed). Else 0.
  double error_bound = 0.0;
  std::vector<uint32_t> remap; // old vertex index -> new index, or kRemoved
  // For each output face, the input face it is (same corners, same order, or reversed if
  // reoriented_faces counts it), or kRemoved for a face the re-triangulation made: lets an
  // adapter keep per-face data of untouched faces.
  std::vector<uint32_t> face_source;
  // With Options::corner_sources: for each output face corner (3 an output face, in order), the
  // input corner (3 * input face + corner) whose per-corner data it takes. The corner is of
  // the same vertex, in a face the new one replaced on the same side of every constrained
  // edge, so with seams constrained the three corners of a face come from one chart.
  std::vector<uint32_t> corner_source;
  // With Options::corner_sources and constrained edges: per output face, bit c set when its
  // side from corner c to corner c + 1 (mod 3) is a constrained edge. A caller that runs the
  // output again (a tiled run's next level) keeps them: two charts may agree on the values at
  // both ends of a side that is a seam between them, and values alone would lose it.
  std::vector<uint8_t> constrained_sides;
};

constexpr uint32_t kRemoved = 0xffffffffu;

// What a front end knows of a run beside its report, for report_json.
struct ReportContext {
  double seconds_simplify = 0; // the run's wall time as the caller measured it
  double seconds_total = -1;   // with reading and writing; < 0: left out
  double diagonal = 0;         // the input's bounding-box diagonal: error_bound_percent
  bool bounded = false;        // an error bound was tracked (Options::max_error > 0)
};

// The report as one JSON object, with the keys every front end gives (docs/report.md): the
// command line's --json, the numpy API's dict, pymeshlab's stop detail and cause. A bound that
// was not tracked is left out, never written as 0 (which would read "no error at all").
std::string report_json(const Report& report, const ReportContext& context);

// Simplifies `mesh` in place: removed vertices are compacted away (kept vertices keep their
// relative order) and triangles rewritten. On invalid input (report.ok == false) the mesh is
// left exactly as given. Deterministic: the same input and options give the same output.
Report simplify(Mesh& mesh, const Options& options);

// The threads Options::threads = 0 stands for: the cores this process may run on (its CPU
// affinity) and is given time on (a container's CPU quota), at least 1. Tiled runs count
// their worker processes with it too.
int usable_cores();

// The options for a run on a piece of a larger input (a tile, a level of detail made from the
// finer one): re-priced as the whole input would be in core (Tuning::lazy_from_faces read
// against `input_faces`), not by the piece's own size.
Options priced_as_input(Options options, size_t input_faces);

// Length of the diagonal of the bounding box of the finite positions (0 when there is none):
// the unit of relative errors (CLI --max-error E%, the plugin's MaxError, the benchmark).
double bounding_box_diagonal(const Mesh& mesh);

// Coordinates read as doubles (a PLY's double properties, a text file's numbers, a float64
// array), as the core's float positions: every front end reads them through these two, so one
// input gives one output whatever reads it. A coordinate is beyond a float when it is finite,
// not a float's value, and not a decimal of at most 7 significant digits (the most a text
// file's float is written with). When none is, each is rounded to its float; else each is
// taken relative to the first vertex whose three coordinates are finite, then rounded (the
// precision a float lacks far from the origin is kept near the mesh). Either way the output's
// vertices are the input's, untouched: the shift moves nothing but the run's rounding.
bool beyond_float(double x);
std::vector<float> float_positions(const double* xyz, size_t vertices);

// The faces as a run with split_vertices Seam or Weld reads them: each corner on the copy that
// stands for its vertex (the input's triangles when nothing is split). An adapter that finds
// seams in per-corner data finds them across split edges too when it reads the faces so (the
// command-line tool and tiled runs do, then run Weld).
std::vector<uint32_t> split_vertex_welded_triangles(const Mesh& mesh);

// Short parsers used by the adapters (CLI, plugin): false on an unknown name.
bool parse_mode(const std::string& s, Mode& out);
bool parse_queue(const std::string& s, QueueKind& out);
bool parse_mapping(const std::string& s, IntervalMapping& out);
bool parse_priority(const std::string& s, Priority& out);
const char* priority_name(Priority p);
bool parse_fill(const std::string& s, Fill& out);
const char* fill_name(Fill f);

} // namespace vrs
