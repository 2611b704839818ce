// The fuzzer's findings, kept as inputs that must now pass every check (fuzz/regressions/),
// and a short deterministic stand-in for the fuzzer in every test run: random byte strings and
// byte-level mutations of real meshes through the same decoder and checks.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include "fuzz_case.h"
#include "test_meshes.h"

namespace fs = std::filesystem;

TEST(FuzzRegressions, EveryFindingNowKeepsTheInvariants) {
  const fs::path dir = VRS_FUZZ_REGRESSIONS;
  ASSERT_TRUE(fs::is_directory(dir)) << dir;
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    std::ifstream in(entry.path(), std::ios::binary);
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), {});
    EXPECT_EQ(vrs_test::run_fuzz_case(bytes.data(), bytes.size()), "") << entry.path();
    ++files;
  }
  EXPECT_GE(files, 4);
}

TEST(FuzzRegressions, RandomBytesKeepTheInvariants) {
  std::mt19937 rng(20261122);
  for (int i = 0; i < 400; ++i) {
    std::vector<uint8_t> bytes(16 + rng() % 3000);
    for (auto& b : bytes)
      b = uint8_t(rng());
    ASSERT_EQ(vrs_test::run_fuzz_case(bytes.data(), bytes.size()), "") << "case " << i;
  }
}

TEST(FuzzRegressions, MutatedRealMeshesKeepTheInvariants) {
  const std::string path = vrs_test::cgal_mesh("cross.off");
  if (path.empty()) GTEST_FAIL() << "cross.off missing: run scripts/setup.sh";
  const vrs::Mesh m = vrs_test::read_off(path);
  std::mt19937 rng(7);
  for (int i = 0; i < 300; ++i) {
    std::vector<uint8_t> bytes =
        vrs_test::encode_fuzz_case(m, uint8_t(rng()), uint8_t(rng() & 0x6f), 1000, rng());
    // Flip a few bytes past the header: coordinates turn into NaN/inf/huge, indices stray.
    for (int k = 0; k < 1 + int(rng() % 8); ++k)
      bytes[14 + rng() % (bytes.size() - 14)] ^= uint8_t(1u << (rng() % 8));
    ASSERT_EQ(vrs_test::run_fuzz_case(bytes.data(), bytes.size()), "") << "case " << i;
  }
}
