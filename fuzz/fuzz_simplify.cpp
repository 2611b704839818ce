// libFuzzer target: any byte string is a mesh and options (tests/support/fuzz_case.h); the run
// must keep every invariant, so a silent corruption is a finding, not only a crash.
#include <cstdio>
#include <cstdlib>

#include "fuzz_case.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string broken = vrs_test::run_fuzz_case(data, size);
  if (!broken.empty()) {
    std::fprintf(stderr, "invariant broken: %s\n", broken.c_str());
    std::abort();
  }
  return 0;
}
