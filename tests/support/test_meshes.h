// Meshes for the tests: a small OFF reader for CGAL's real data, hand-built cases, generators.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "vrs/simplify.h"

namespace vrs_test {

// Reads an OFF file (OFF/COFF/NOFF, comments, polygons fan-triangulated). Empty on failure.
vrs::Mesh read_off(const std::string& path);
// Path of a mesh of CGAL's data set (VRS_CGAL_DATA), or "" when the data set is missing.
std::string cgal_mesh(const std::string& name);

// Flat regular hexagon around one centre vertex (index 6), in the z = 0 plane.
vrs::Mesh hexagon_fan(float centre_height = 0.0f);
// Closed fan whose ring is the concave "arrow" polygon: needs ear clipping, not a fan.
vrs::Mesh concave_fan();
vrs::Mesh tetrahedron();
// Open n x n grid of squares (two triangles each) in the z = 0 plane, jittered deterministically
// in xy so that the interior is not degenerate for the fan chooser.
vrs::Mesh grid(int n, float jitter = 0.0f);
// Height field z = f(x, y) on an n x n grid: a smooth sum of bumps.
vrs::Mesh terrain(int n);
// Icosphere: 20 * 4^level triangles, closed, genus 0.
vrs::Mesh icosphere(int level);
// Meshes of every kind a run meets, for the tests that compare runs with each other (thread
// counts, parts): an open terrain, a closed icosphere and CGAL's elephant, fandisk and
// mushroom when the data set is there.
struct NamedMesh {
  std::string name;
  vrs::Mesh mesh;
};
std::vector<NamedMesh> comparison_meshes();
// The thread counts those tests compare one thread against: 2, 3 and 8, or the ones the
// environment's VRS_TEST_THREAD_COUNTS lists ("2,8" in the ThreadSanitizer lanes, where a run
// takes 20 times as long: races need threads, not every count).
std::vector<int> compared_thread_counts();
// A closed plate of nx x ny unit cells, `thickness` thick, with a square through-hole at each
// cell (x, y) listed in `holes` (pairs): genus = the number of holes. Each cell is two
// triangles on each side; the walls are split `wall_rows` times along the thickness (a CAD
// tessellation's long thin triangles).
vrs::Mesh plate_with_holes(int nx, int ny, const std::vector<std::pair<int, int>>& holes,
                           float thickness, int wall_rows = 1);

// A cylinder of `bands` bands of `rows` rows of quads, alternately 2n and n columns around:
// where a coarse band meets a fine one the two share every other vertex of the fine band's
// edge row and no edge, a crack whose shared vertices are each two open fans (CGAL's pig.stl
// has 421 of them).
vrs::Mesh cracked_cylinder(int bands, int rows, int n);

} // namespace vrs_test
