// libFuzzer target of the tiled runs' streaming readers: any bytes, read as PLY, OBJ or OFF
// (the first byte picks: its value modulo 3), must give a message or a stream of vertices and
// triangles, never a crash, a hang or an allocation the input does not pay for. Cheap per input, so
// it runs thousands of executions a second (the core's target: ~50).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "mesh_stream.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  static const char* const names[3] = {"in.ply", "in.obj", "in.off"};
  const std::string name = names[data[0] % 3];
  std::FILE* f = fmemopen(const_cast<uint8_t*>(data + 1), size - 1, "rb");
  if (!f) return 0;
  uint64_t vertices = 0, triangles = 0;
  vrs::tiled::StreamSink sink;
  sink.vertex = [&](const double*) { ++vertices; };
  sink.triangle = [&](const int64_t*, const vrs::tiled::CornerKeys&) { ++triangles; };
  sink.raw_vertex = [](const char*, size_t) {};
  sink.other_line = [](const std::string&) {};
  const std::string error = vrs::tiled::read_mesh_stream(f, name, sink);
  std::fclose(f);
  // A polygon of k corners makes k - 2 triangles: never more triangles than bytes read.
  if (triangles > 8 * size + 8) std::abort();
  (void)error;
  return 0;
}
