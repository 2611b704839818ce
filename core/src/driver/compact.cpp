// The run's end: the mesh in the output's numbering (write/output.h), with the copies the
// set-up made (fan_split.h, split_vertices.h) folded back into the input's vertices.
#include "driver/simplifier.h"
#include "write/output.h"

namespace vrs {

void Simplifier::compact() {
  std::vector<uint8_t> removed(flags_.size());
  for (size_t v = 0; v < flags_.size(); ++v)
    removed[v] = flags_[v] & kFlagRemoved;
  if (!fans_.empty()) { // a copy that stays is its original again (fan_split.h)
    const size_t n = order_.vertex_new.size();
    for (size_t i = 0; i < fans_.original.size(); ++i) {
      const uint32_t o = fans_.original[i];
      // Removals counted are input vertices gone: not a copy, nor an original a copy revives.
      if (removed[n + i])
        --rep_.removed;
      else if (removed[o])
        removed[o] = 0, --rep_.removed;
    }
    for (uint32_t& v : mesh_.triangles)
      if (v != kNone && v >= n) v = fans_.original[v - n];
    removed.resize(n);
    mesh_.positions.resize(3 * n);
  }
  // A welded copy goes where the copy standing for it goes.
  for (size_t i = 0; i < welding_.rep.size(); ++i)
    removed[order_.vertex_new[i]] = removed[order_.vertex_new[welding_.rep[i]]];
  // Which sides are constrained, read before the triangles leave the run's numbering.
  const bool sides = opt_.corner_sources && constraints_.active() && fans_.empty();
  write_output(mesh_, order_, removed,
               {kept_faces_, corner_source_, face_bound_, welding_.corners, welding_.rep, turned_,
                sides ? &constraints_ : nullptr},
               rep_, &workers_);
  if (!opt_.corner_sources) std::vector<uint32_t>().swap(rep_.corner_source);
}

} // namespace vrs
