// Seed corpus for the fuzzer: real meshes (OFF) encoded in its input format, each under a few
// option sets (targets, modes, queue, priority, boundary, locks, cancel).
//   vrs_fuzz_seeds OUT_DIR MESH.off...
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_case.h"
#include "test_meshes.h"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: vrs_fuzz_seeds OUT_DIR MESH.off...\n");
    return 2;
  }
  const std::string out = argv[1];
  struct Variant {
    uint8_t f0, f1;
    uint32_t param;
  };
  // f0: target kind (5-7: 0-2 in parts of 64 vertices) | mode << 3 | heap 0x20 | log 0x40 |
  // boundary 0x80;
  // f1: factor 1 | raw 2 | locks 4 | cancel 8 | constrained edges 32 | feature angle 64 |
  // projection fill only 128.
  const Variant variants[] = {
      {2, 0, 0x19999999u},             // ratio 10 %, local error
      {2 | 0x80, 1, 0x028f5c28u},      // ratio 1 %, boundary too, paper's factor
      {4 | 0x40, 0, 0},                // auto, log mapping
      {0 | 0x20, 4, 40},               // faces, heap, locks
      {3 | (1 << 3), 8, 500},          // max factor, terrain, cancel
      {2, 32, 0x19999999u},            // ratio 10 %, seams, corner sources
      {2 | 0x80, 64, 0x0000002du},     // ratio ~0 %, boundary too, 45 degree creases
      {7, 0, 0x19999999u},             // ratio 10 %, in parts
      {7 | 0x80, 32 | 4, 0x028f5c28u}, // ratio 1 %, in parts, boundary, seams, locks
  };
  int written = 0;
  // `m` under each option set, as NAME.0, NAME.1, ...
  auto write = [&](const vrs::Mesh& m, const std::string& name, const Variant* begin,
                   const Variant* end) {
    int k = 0;
    for (const Variant* v = begin; v != end; ++v) {
      auto bytes = vrs_test::encode_fuzz_case(m, v->f0, v->f1, 1000, v->param);
      std::ofstream(out + "/" + name + "." + std::to_string(k++), std::ios::binary)
          .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
      ++written;
    }
  };
  // A cracked mesh (bands that touch only at points): its vertices where fans meet are split
  // for the run (fan_split.h); under every option set.
  write(vrs_test::cracked_cylinder(5, 3, 8), "cracked", std::begin(variants), std::end(variants));
  for (int i = 2; i < argc; ++i) {
    vrs::Mesh m = vrs_test::read_off(argv[i]);
    if (i == 2) { // the first mesh also with its upper faces on copies of the shared vertices
      vrs::Mesh split = m;
      std::vector<uint8_t> upper(m.face_count()), used(m.vertex_count(), 0);
      double mean = 0;
      for (size_t v = 0; v < m.vertex_count(); ++v)
        mean += m.positions[3 * v + 2] / double(m.vertex_count());
      for (size_t f = 0; f < m.face_count(); ++f) {
        double z = 0;
        for (int c = 0; c < 3; ++c)
          z += m.positions[3 * m.triangles[3 * f + c] + 2] / 3.0;
        upper[f] = z > mean;
        for (int c = 0; c < 3; ++c)
          used[m.triangles[3 * f + c]] |= upper[f] ? 2 : 1;
      }
      std::vector<uint32_t> copy(m.vertex_count(), 0xffffffffu);
      for (uint32_t v = 0; v < m.vertex_count(); ++v)
        if (used[v] == 3) {
          copy[v] = uint32_t(split.vertex_count());
          for (int a = 0; a < 3; ++a)
            split.positions.push_back(m.positions[3 * v + a]);
        }
      for (size_t f = 0; f < m.face_count(); ++f)
        for (int c = 0; c < 3 && upper[f]; ++c)
          if (copy[m.triangles[3 * f + c]] != 0xffffffffu)
            split.triangles[3 * f + c] = copy[m.triangles[3 * f + c]];
      // Seams (the default) and welded freely (mode bits 3), at 10 % and 1 %.
      const Variant split_variants[] = {{2, 0, 0x19999999u},
                                        {2 | (3 << 3), 0, 0x19999999u},
                                        {2 | 0x80 | (3 << 3), 4, 0x028f5c28u}};
      write(split, "split", std::begin(split_variants), std::end(split_variants));
    }
    if (m.vertex_count() == 0 || m.vertex_count() > 65535) {
      std::fprintf(stderr, "skipped %s\n", argv[i]);
      continue;
    }
    std::string base = argv[i];
    base = base.substr(base.find_last_of('/') + 1);
    write(m, base, std::begin(variants), std::end(variants));
  }
  std::printf("%d seeds in %s\n", written, out.c_str());
  return written > 0 ? 0 : 1;
}
