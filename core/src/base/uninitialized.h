// A vector whose resize() leaves new elements unwritten: large arrays the workers fill block
// by block (a value-initialized resize is a serial memset of the whole array first; fill_on in
// workers.h).
#pragma once

#include <memory>
#include <vector>

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

} // namespace vrs
