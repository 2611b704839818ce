#include "progressive_faces.h"

#include <algorithm>
#include <map>
#include <utility>

namespace vrs {

// The base rule: sides in order, at most one waiting for each way between two vertices; a side
// from a to b pairs with the one waiting from b to a, else waits unless one from a to b does.
ProgressiveFaces::ProgressiveFaces(const std::vector<uint32_t>& base)
    : corners_(base), across_(base.size(), kNone) {
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> waiting;
  for (uint32_t s = 0; s < corners_.size(); ++s) {
    const uint32_t a = corners_[s], b = corners_[next_corner(s)];
    const auto back = waiting.find({b, a});
    if (back != waiting.end()) {
      across_[s] = back->second;
      across_[back->second] = s;
      waiting.erase(back);
    } else {
      waiting.emplace(std::make_pair(a, b), s); // no second waits
    }
  }
}

// The walk: a list that starts with `first`; for each face of the list in turn, each of its
// sides in order whose face across is not in the list yet costs one bit, 1 to append that face.
// It stops as soon as the list is long enough.
bool ProgressiveFaces::walk(uint32_t first, const std::vector<uint32_t>& patch,
                            std::vector<uint32_t>& order, std::vector<uint8_t>& bits) const {
  const size_t want = patch.size();
  auto in = [](const std::vector<uint32_t>& v, uint32_t x) {
    return std::find(v.begin(), v.end(), x) != v.end();
  };
  order.assign(1, first);
  bits.clear();
  for (size_t i = 0; order.size() < want; ++i) {
    if (i == order.size()) return false;
    for (int c = 0; c < 3 && order.size() < want; ++c) {
      const uint32_t t = across_[3 * size_t(order[i]) + c];
      if (t == kNone || in(order, t / 3)) continue;
      const bool take = in(patch, t / 3);
      bits.push_back(take);
      if (take) order.push_back(t / 3);
    }
  }
  return in(patch, first);
}

void ProgressiveFaces::outline(const std::vector<uint32_t>& patch,
                               std::vector<OutlineSide>& out) const {
  out.clear();
  for (uint32_t p : patch)
    for (uint32_t c = 0; c < 3; ++c) {
      const uint32_t s = 3 * p + c, t = across_[s];
      if (t != kNone && std::find(patch.begin(), patch.end(), t / 3) != patch.end()) continue;
      out.push_back({corners_[s], corners_[next_corner(s)], t});
    }
}

// The record rule: the outline's sides with a face across are the patch's outer sides (those
// faces lose their pairing); then each new side in order, unless already paired, pairs with the
// first unused outer side that runs the same way, else with the first later new side that runs
// back, else with none.
void ProgressiveFaces::write(const std::vector<uint32_t>& patch, const std::vector<Face>& faces) {
  outline(patch, outline_);
  std::vector<Outer>& outer = outer_;
  outer.clear();
  for (const OutlineSide& o : outline_) {
    if (o.across == kNone) continue;
    outer.push_back({o.a, o.b, o.across, false});
    across_[o.across] = kNone;
  }
  std::vector<uint32_t>& sides = sides_; // the new faces' sides, in order
  sides.clear();
  for (size_t i = 0; i < faces.size(); ++i) {
    uint32_t slot;
    if (i < patch.size()) {
      slot = patch[i];
    } else {
      slot = uint32_t(size());
      corners_.resize(corners_.size() + 3);
      across_.resize(across_.size() + 3);
    }
    for (uint32_t c = 0; c < 3; ++c) {
      corners_[3 * size_t(slot) + c] = faces[i][c];
      across_[3 * size_t(slot) + c] = kNone;
      sides.push_back(3 * slot + c);
    }
  }
  for (size_t i = 0; i < sides.size(); ++i) {
    const uint32_t s = sides[i];
    if (across_[s] != kNone) continue;
    const uint32_t a = corners_[s], b = corners_[next_corner(s)];
    bool paired = false;
    for (Outer& o : outer)
      if (!o.used && o.a == a && o.b == b) {
        o.used = paired = true;
        across_[s] = o.side;
        across_[o.side] = s;
        break;
      }
    for (size_t j = i + 1; j < sides.size() && !paired; ++j) {
      const uint32_t t = sides[j];
      if (across_[t] == kNone && corners_[t] == b && corners_[next_corner(t)] == a) {
        paired = true;
        across_[s] = t;
        across_[t] = s;
      }
    }
  }
}

} // namespace vrs
