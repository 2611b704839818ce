// How a progressive record writes numbers (docs/progressive.md): varints, bits, and each new
// vertex's attributes as residuals from a prediction the decoder makes too, the mean of the
// older vertices its faces touch, in Rice codes. Floats are subtracted as ordered integers, so
// that the coding is lossless and a close prediction costs few bits.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace vrs {

// The Rice codes' escape (that many ones) and how many bits below the spread's length a
// residual's parameter is (docs/progressive.md).
constexpr int kRiceEscape = 16;
constexpr int kRiceSpreadShift = 3;

inline void put_varint(std::vector<uint8_t>& out, uint64_t x) {
  while (x >= 0x80) {
    out.push_back(uint8_t(x | 0x80));
    x >>= 7;
  }
  out.push_back(uint8_t(x));
}

// Bits appended lowest first; the last byte is padded with zeros when the writer goes.
class BitWriter {
 public:
  explicit BitWriter(std::vector<uint8_t>& out) : out_(out) {}
  ~BitWriter() {
    if (count_) out_.push_back(uint8_t(pending_));
  }
  void put(uint64_t value, int width) {
    for (int i = 0; i < width; ++i) {
      pending_ |= uint32_t((value >> i) & 1) << count_;
      if (++count_ == 8) {
        out_.push_back(uint8_t(pending_));
        pending_ = count_ = 0;
      }
    }
  }

 private:
  std::vector<uint8_t>& out_;
  uint32_t pending_ = 0;
  int count_ = 0;
};

// A vertex's attributes in the order they are coded: each a group of floats (position, normal,
// texture coordinates) or of bytes (color), at its offset.
struct VertexFields {
  struct Group {
    uint32_t at, count;
    bool floats;
  };
  std::vector<Group> groups;
  VertexFields(int normal_at, int color_at, int uv_at) {
    groups.push_back({0, 3, true});
    if (normal_at >= 0) groups.push_back({uint32_t(normal_at), 3, true});
    if (color_at >= 0) groups.push_back({uint32_t(color_at), 4, false});
    if (uv_at >= 0) groups.push_back({uint32_t(uv_at), 2, true});
  }
};

// A float's bits as an integer that orders the floats as their values do.
inline int64_t ordered_bits(float x) {
  int32_t b;
  std::memcpy(&b, &x, 4);
  return b < 0 ? int64_t(b ^ 0x7fffffff) : int64_t(b);
}

inline uint64_t zigzag(int64_t d) {
  return d >= 0 ? uint64_t(d) << 1 : (uint64_t(-d) << 1) - 1;
}

inline int bit_length(uint64_t x) {
  int n = 0;
  for (; x; x >>= 1)
    ++n;
  return n;
}

// A residual's zigzag `z` as a Rice code whose `k` low bits are written as they are: q = z >> k
// ones and a zero, then the k bits; from 16 ones on, the ones end there and z follows as its
// bit length (6 bits) and its bits.
inline void put_rice(BitWriter& bits, uint64_t z, int k) {
  const uint64_t q = z >> k;
  if (q < kRiceEscape) {
    bits.put((uint64_t(1) << q) - 1, int(q) + 1);
    bits.put(z, k);
  } else {
    bits.put((uint64_t(1) << kRiceEscape) - 1, kRiceEscape);
    bits.put(uint64_t(bit_length(z)), 6);
    bits.put(z, bit_length(z));
  }
}

// The Rice parameter of a value whose known vertices lie up to `spread` from its prediction
// (in the units the residual counts): residuals run about as wide as the ring does.
inline int rice_parameter(uint64_t spread) {
  return std::max(0, bit_length(spread) - kRiceSpreadShift);
}

// The residuals of the vertex at `actual` against the mean of `known` (each a vertex's bytes);
// with none known, against `fallback` (nullptr: zeros): each value's zigzagged residual as a
// Rice code, its parameter from how far the known vertices' own values lie from the prediction.
inline void put_residuals(BitWriter& out, const VertexFields& fields, const uint8_t* actual,
                          const std::vector<const uint8_t*>& known, const uint8_t* fallback) {
  for (const VertexFields::Group& g : fields.groups)
    for (uint32_t i = 0; i < g.count; ++i) {
      uint64_t spread = 0;
      if (g.floats) {
        const uint32_t at = g.at + 4 * i;
        float predicted = 0, x;
        if (!known.empty()) {
          double sum = 0;
          for (const uint8_t* v : known) {
            std::memcpy(&x, v + at, 4);
            sum += double(x);
          }
          predicted = float(sum / double(known.size()));
        } else if (fallback) {
          std::memcpy(&predicted, fallback + at, 4);
        }
        const int64_t p = ordered_bits(predicted);
        for (const uint8_t* v : known) {
          std::memcpy(&x, v + at, 4);
          spread = std::max(spread, uint64_t(std::llabs(ordered_bits(x) - p)));
        }
        std::memcpy(&x, actual + at, 4);
        put_rice(out, zigzag(ordered_bits(x) - p), rice_parameter(spread));
      } else {
        const uint32_t at = g.at + i;
        int64_t predicted = 0;
        if (!known.empty()) {
          double sum = 0;
          for (const uint8_t* v : known)
            sum += v[at];
          predicted = int64_t(std::floor(sum / double(known.size()) + 0.5));
        } else if (fallback) {
          predicted = fallback[at];
        }
        for (const uint8_t* v : known)
          spread = std::max(spread, uint64_t(std::llabs(int64_t(v[at]) - predicted)));
        put_rice(out, zigzag(int64_t(actual[at]) - predicted), rice_parameter(spread));
      }
    }
}

} // namespace vrs
