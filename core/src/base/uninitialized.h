// A vector whose resize() leaves new elements unwritten: large arrays the workers fill block
// by block (a value-initialized resize is a serial memset of the whole array first).
#pragma once

#include <algorithm>
#include <memory>
#include <vector>

#include "base/workers.h"

namespace vrs {

template <class T> struct DefaultInit : std::allocator<T> {
  template <class U> struct rebind { using other = DefaultInit<U>; };
  DefaultInit() = default;
  template <class U> DefaultInit(const DefaultInit<U>&) noexcept {}
  template <class U> void construct(U* p) noexcept { ::new (static_cast<void*>(p)) U; }
  template <class U, class... Args> void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <class T> using UninitVector = std::vector<T, DefaultInit<T>>;

// v holds n copies of x, written block by block on the workers (null: on the caller).
template <class T> void fill_on(Workers* workers, UninitVector<T>& v, size_t n, const T& x) {
  v.resize(n);
  for_each_block(workers, n, 65536, [&](size_t begin, size_t end) {
    std::fill(v.begin() + begin, v.begin() + end, x);
  });
}

} // namespace vrs
