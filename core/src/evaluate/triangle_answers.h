// The answers one thread's questions to the input surface gave, by triangle: whether a new
// triangle folds against the input depends on nothing but its three corners (input vertices,
// never moved), the question and the input, so a plan that makes a triangle asked before (a
// ring priced again after one neighbour went keeps most of its filling) reads the answer
// instead of asking a grid of points again. Direct-mapped: a newer triangle takes the slot
// of an older one; an answer read is always the one asked, so the output never depends on
// what the table holds.
#pragma once

#include <cstdint>
#include <cstring>
#include <memory>

#include "base/geometry.h"

namespace vrs {

class TriangleAnswers {
 public:
  // A question: the triangle's corners in order, which surface (InputSurface's id), and the
  // question's own terms (kind and parameters, as the asker names them).
  struct Question {
    float corner[9];
    uint32_t kind;
    uint64_t surface;
    double terms[2];
    bool operator==(const Question& o) const { return std::memcmp(this, &o, sizeof o) == 0; }
  };
  // The question, when every corner is a float (the mesh's positions are): false for other
  // points, which the table cannot tell apart by their floats.
  static bool question(Vec3 a, Vec3 b, Vec3 c, uint64_t surface, uint32_t kind, double t0,
                       double t1, Question& q) {
    std::memset(&q, 0, sizeof q); // padding too: questions compare as bytes
    const Vec3 p[3] = {a, b, c};
    for (int i = 0; i < 3; ++i) {
      const double x[3] = {p[i].x, p[i].y, p[i].z};
      for (int k = 0; k < 3; ++k) {
        q.corner[3 * i + k] = float(x[k]);
        if (!(double(q.corner[3 * i + k]) == x[k])) return false;
      }
    }
    q.kind = kind, q.surface = surface, q.terms[0] = t0, q.terms[1] = t1;
    return true;
  }
  // This thread's table.
  static TriangleAnswers& here() {
    thread_local TriangleAnswers answers;
    return answers;
  }
  bool find(const Question& q, double& answer) const {
    if (!slots_) return false;
    const Slot& s = slots_[slot_of(q)];
    if (!s.used || !(s.question == q)) return false;
    answer = s.answer;
    return true;
  }
  void store(const Question& q, double answer) {
    if (!slots_) slots_.reset(new Slot[kSlots]());
    Slot& s = slots_[slot_of(q)];
    s.question = q, s.answer = answer, s.used = true;
  }

 private:
  static constexpr size_t kSlots = size_t(1) << 14;
  struct Slot {
    Question question;
    double answer;
    bool used;
  };
  static size_t slot_of(const Question& q) {
    uint64_t h = 1469598103934665603ull; // FNV-1a over the question's bytes
    const unsigned char* p = reinterpret_cast<const unsigned char*>(&q);
    for (size_t i = 0; i < sizeof q; ++i)
      h = (h ^ p[i]) * 1099511628211ull;
    return size_t(h ^ (h >> 29)) & (kSlots - 1);
  }
  std::unique_ptr<Slot[]> slots_;
};

} // namespace vrs
