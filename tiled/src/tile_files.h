// The files a tiled run keeps in its work directory, and how they are written: every file is
// written under a temporary name and renamed when complete, so a killed worker leaves either
// nothing or a whole file (a re-run of its tile simply writes it again).
//   vertices.bin        the input's positions, double xyz, in input order (for the tiles)
//   faces.bin           the input's triangles, uint32 x3 (level 1 reads it)
//   keys.bin            their CornerKeys, when the input has per-corner data
//   polygons.bin        an OBJ's or OFF's faces of more than three corners (PolygonRecord);
//                       faces.bin is then kept to the end, for the output to find them whole
//   materials           an OBJ's material names, one a line, by group number
//   state               the run's settings and where it stands (key value lines)
//   L<level>/<tile>.in  one tile's faces as records (below), shared vertices marked
//   L<level>/<tile>.out the tile simplified, as records
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace vrs::tiled {

// A face with its corners' global (input) vertex ids, positions and per-corner keys (see
// CornerKeys in mesh_stream.h): a tile needs nothing else. Without per-corner data in the
// input the keys are zero and not written: a record is then its first kShortRecord bytes.
struct FaceRecord {
  uint32_t v[3];
  float p[3][3];
  uint8_t shared;  // bit c: corner c's vertex is also in another tile (a border)
  uint8_t polygon; // 1: an untouched triangle of one of the input's polygons (polygons.bin)
  // Bit c: the side from corner c to corner c + 1 was a constrained edge (a seam) of the level
  // that wrote the record (vrs::Report::constrained_sides); kept, seam or not by its values.
  uint8_t seam_sides;
  uint8_t pad;
  uint32_t a[3], b[3], group;
};
static_assert(sizeof(FaceRecord) == 80, "records are written as they are");
constexpr size_t kShortRecord = 52;
inline size_t record_size(bool keys) {
  return keys ? sizeof(FaceRecord) : kShortRecord;
}

// A face of more than three corners, fanned from its first corner into the triangles
// first, first + 1, ..., first + corners - 3 of faces.bin.
struct PolygonRecord {
  uint64_t first;
  uint32_t corners, pad;
};

// Buffered writer to `path`, visible under that name only after commit().
class RecordWriter {
 public:
  // Durable: flushed to the disk before the rename (the output). Tile files are not: they are
  // one run's temporaries, a crash ends the run anyway, and syncing them cost 9 of the 23 s
  // of the 77 M-face streaming pass. The rename alone keeps readers from a partial file.
  explicit RecordWriter(std::string path, bool durable = false);
  ~RecordWriter(); // without commit: the temporary is removed
  RecordWriter(const RecordWriter&) = delete;
  RecordWriter& operator=(const RecordWriter&) = delete;
  void write(const void* data, size_t bytes);
  void commit(); // throws on a write error (a full disk)
  const std::string& path() const { return path_; }

 private:
  std::string path_, tmp_;
  std::FILE* f_ = nullptr;
  bool durable_ = false;
};

// Calls fn for each record of the file (records with keys or short ones); throws if it cannot
// be read whole.
void for_each_record(const std::string& path, bool keys,
                     const std::function<void(const FaceRecord&)>& fn);
uint64_t record_count(const std::string& path, bool keys);

// The state file: ordered key -> value text.
using State = std::map<std::string, std::string>;
State read_state(const std::string& dir);
void write_state(const std::string& dir, const State& s);
double state_number(const State& s, const std::string& key);

std::string tile_path(const std::string& dir, int level, size_t tile, const char* ext);
void make_dir(const std::string& path); // throws with the reason
void remove_tree(const std::string& path);

} // namespace vrs::tiled
