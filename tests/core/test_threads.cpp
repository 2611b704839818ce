// The workers, and the promise that the output does not depend on the thread count (nor does
// a lazy or eager re-pricing break an invariant).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#if defined(__linux__)
#include <sched.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <string>
#endif

#include "base/cores.h"
#include "base/workers.h"
#include "mesh_checks.h"
#include "test_meshes.h"

using namespace vrs;

TEST(Workers, EveryItemRunsOnceWhateverTheThreadsAndGrain) {
  for (int threads : {1, 2, 3, 8})
    for (size_t grain : {size_t(1), size_t(4), size_t(100)})
      for (size_t n : {size_t(0), size_t(1), size_t(5), size_t(1000)}) {
        Workers w(threads);
        EXPECT_EQ(w.threads(), threads);
        std::vector<std::atomic<int>> hits(n);
        for (int round = 0; round < 3; ++round) // the same threads serve loop after loop
          w.for_each(
              n, [&](size_t i) { hits[i].fetch_add(1); }, grain);
        for (size_t i = 0; i < n; ++i)
          ASSERT_EQ(hits[i].load(), 3) << "item " << i << ", " << threads << " threads";
      }
}

// The default thread count is the cores the process may run on: pinned to one core (as
// `taskset -c 0` pins a run), one thread; to two, two at most (a container's quota may grant
// fewer). Threads past those would only wait for a core.
TEST(UsableCores, FollowTheAffinity) {
#if defined(__linux__)
  cpu_set_t before;
  ASSERT_EQ(sched_getaffinity(0, sizeof before, &before), 0);
  std::vector<int> allowed;
  for (int c = 0; c < CPU_SETSIZE; ++c)
    if (CPU_ISSET(c, &before)) allowed.push_back(c);
  ASSERT_FALSE(allowed.empty());
  EXPECT_LE(usable_cores(), int(allowed.size()));
  for (size_t n : {size_t(1), size_t(2)}) {
    if (n > allowed.size()) break;
    cpu_set_t some;
    CPU_ZERO(&some);
    for (size_t i = 0; i < n; ++i)
      CPU_SET(allowed[i], &some);
    ASSERT_EQ(sched_setaffinity(0, sizeof some, &some), 0);
    const int cores = usable_cores();
    EXPECT_GE(cores, 1);
    EXPECT_LE(cores, int(n)) << n << " cores allowed";
    if (n == 1) {
      EXPECT_EQ(cores, 1);
    }
    // A run on the default count there: the same output as on one thread.
    Mesh a = vrs_test::icosphere(3), b = a;
    Options o;
    o.target.kind = TargetKind::Faces;
    o.target.faces = a.face_count() / 5;
    o.threads = 0;
    ASSERT_TRUE(simplify(a, o).ok);
    o.threads = 1;
    ASSERT_TRUE(simplify(b, o).ok);
    EXPECT_EQ(a.triangles, b.triangles);
  }
  ASSERT_EQ(sched_setaffinity(0, sizeof before, &before), 0);
#else
  GTEST_SKIP() << "affinity masks: Linux";
#endif
}

// A real CPU quota of half a core (a cgroup of its own, as `docker --cpus 0.5` makes one): a
// process in it counts one core. Needs root and a writable cgroup hierarchy (v1's cpu
// controller or v2's cpu.max); skipped elsewhere. The cgroup is removed afterwards.
TEST(UsableCores, AContainersQuotaLimitsThem) {
#if defined(__linux__)
  const std::string name = "vrs_test_quota_" + std::to_string(getpid());
  struct Layout {
    std::string dir, file, quota;
  };
  const Layout layouts[] = {{"/sys/fs/cgroup/cpu/" + name, "cpu.cfs_quota_us", "50000"},
                            {"/sys/fs/cgroup/" + name, "cpu.max", "50000 100000"}};
  for (const Layout& l : layouts) {
    if (mkdir(l.dir.c_str(), 0755) != 0) continue;
    const bool set = bool(std::ofstream(l.dir + "/" + l.file) << l.quota << std::endl);
    int cores = -1;
    if (set) {
      const pid_t child = fork();
      if (child == 0) { // into the cgroup, then count
        const bool in = bool(std::ofstream(l.dir + "/cgroup.procs") << getpid() << std::endl);
        _exit(in ? std::min(usable_cores(), 100) : 101);
      }
      int status = 0;
      if (child > 0 && waitpid(child, &status, 0) == child && WIFEXITED(status))
        cores = WEXITSTATUS(status);
    }
    rmdir(l.dir.c_str());
    if (cores < 0 || cores > 100) continue; // not allowed here: the next layout
    EXPECT_EQ(cores, 1) << "a quota of half a core (" << l.dir << ")";
    return;
  }
  GTEST_SKIP() << "no cgroup of our own can be made here (needs root, a writable hierarchy)";
#else
  GTEST_SKIP() << "cgroups: Linux";
#endif
}

// A container's CPU quota, as cgroup v2 (cpu.max) and v1 (quota and period) write it.
TEST(UsableCores, AQuotaGrantsItsCoresRoundedUp) {
  EXPECT_EQ(cores_in_quota("50000 100000\n"), 1);
  EXPECT_EQ(cores_in_quota("100000 100000"), 1);
  EXPECT_EQ(cores_in_quota("150000 100000"), 2);
  EXPECT_EQ(cores_in_quota("400000 100000\n"), 4);
  EXPECT_EQ(cores_in_quota("max 100000\n"), 0);
  EXPECT_EQ(cores_in_quota(""), 0);
  EXPECT_EQ(cores_in_quota("garbage"), 0);
  EXPECT_EQ(cores_in_quota("12x 100000"), 0);
  EXPECT_EQ(cores_in_quota(-1, 100000), 0);
  EXPECT_EQ(cores_in_quota(250000, 100000), 3);
  EXPECT_EQ(cores_in_quota(100000, 0), 0);
}

// The projection to more threads (bench/SPEED.md, "by chunks"): each loop's own time in rounds
// of its chunks. Arithmetic on the times measured, so exact whatever the machine's speed.
TEST(Workers, LoopsAreProjectedInRoundsOfTheirChunks) {
  auto spin = [](size_t) {
    volatile double x = 0;
    for (int k = 0; k < 200; ++k) // short chunks (under a 50 us chunk): rounds of their mean
      x = x + std::sqrt(double(k));
  };
  struct Case {
    size_t n, grain;
    bool ranges;
    double rounds8, rounds16; // the share of the loop's time on 8 and 16 threads
  };
  for (const Case& c : {Case{1, 1, false, 1.0, 1.0}, // one chunk: one thread at any count
                        Case{3, 4, false, 1.0, 1.0}, // under a grain: one chunk too
                        Case{32, 1, false, 4.0 / 32, 2.0 / 32},
                        Case{20, 1, false, 3.0 / 20, 2.0 / 20}, // 20 chunks: two rounds on 16
                        Case{40, 4, false, 2.0 / 10, 1.0 / 10},
                        Case{1, 1, true, 1.0 / 8, 1.0 / 16}}) { // a range a thread
    Workers w(1);
    if (c.ranges)
      w.for_each_range(c.n, spin);
    else
      w.for_each(c.n, spin, c.grain);
    const double t = w.parallel_seconds();
    ASSERT_GT(t, 0.0);
    EXPECT_NEAR(w.span_seconds(8), t * c.rounds8, 1e-12 * t) << c.n << " items, grain " << c.grain;
    EXPECT_NEAR(w.span_seconds(16), t * c.rounds16, 1e-12 * t)
        << c.n << " items, grain " << c.grain;
  }
}

// Long chunks (the parts) are timed one by one and handed out in order to the first free
// thread: a long chunk last makes the loop at least as long as it and the chunks before it
// that its thread ran, whatever the mean (rounds of the mean said 2 x 36/17 ms on 16 threads).
TEST(Workers, LongChunksAreProjectedAsHandedOutToTheFirstFreeThread) {
  auto busy = [](double seconds) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < until) {
    }
  };
  for (const bool long_first : {true, false}) {
    Workers w(1);
    const size_t long_one = long_first ? 0 : 16;
    w.for_each(
        17, [&](size_t i) { busy(i == long_one ? 20e-3 : 1e-3); }, 1);
    const double t = w.parallel_seconds();
    ASSERT_GE(t, 36e-3);
    // First: the long one runs beside all the others (16: the 16 short ones on 15 threads,
    // 8: on 7). Last: it waits for a thread to finish its short one.
    for (int threads : {8, 16}) {
      const double floor = long_first ? 20e-3 : 21e-3;
      EXPECT_GE(w.span_seconds(threads), floor) << threads << " threads, long first " << long_first;
      // No more than the long one, its thread's short ones and a slack for a loaded machine.
      EXPECT_LT(w.span_seconds(threads), t - 10e-3) << threads << " threads";
    }
  }
}

namespace {

struct Outcome {
  Mesh mesh;
  Report report;
};

Outcome run(const Mesh& in, Options o, int threads) {
  Outcome r{in, {}};
  o.threads = threads;
  r.report = simplify(r.mesh, o);
  return r;
}

void expect_same(const Outcome& a, const Outcome& b, const std::string& what) {
  EXPECT_TRUE(vrs_test::same_bits(a.mesh, b.mesh)) << what;
  EXPECT_EQ(a.report.removed, b.report.removed) << what;
  EXPECT_EQ(a.report.stop, b.report.stop) << what;
  EXPECT_EQ(a.report.stop_detail, b.report.stop_detail) << what;
  EXPECT_EQ(a.report.relaxed_removals, b.report.relaxed_removals) << what;
  EXPECT_EQ(a.report.slid, b.report.slid) << what;
  for (int r = 0; r < RejectCount; ++r)
    EXPECT_EQ(a.report.rejected[r], b.report.rejected[r]) << what << ", " << reject_name(Reject(r));
  EXPECT_EQ(a.report.face_source, b.report.face_source) << what;
  EXPECT_EQ(a.report.corner_source, b.report.corner_source) << what;
  EXPECT_EQ(a.report.max_removed_factor, b.report.max_removed_factor) << what;
}

} // namespace

TEST(Threads, SameOutputAndReportWhateverTheThreadCount) {
  const auto cases = vrs_test::comparison_meshes();
  ASSERT_GE(cases.size(), 5u) << "CGAL's data set is missing";
  for (const auto& c : cases)
    for (int variant = 0; variant < 8; ++variant) {
      Options o;
      o.target.ratio = variant == 6 ? 0.01 : 0.1;
      o.corner_sources = true;
      switch (variant) {
      case 1: o.simplify_boundary = true; break;
      case 2: o.tuning.priority = Priority::Factor; break;
      case 3: o.tuning.lazy_reevaluation = false; break;
      case 4: o.feature_angle_deg = 40; break;
      case 5: o.mode = c.name == "terrain" ? Mode::Terrain25D : Mode::Surface3D; break;
      case 7: o.tuning.lazy_from_faces = 0; break; // lazy on these small meshes too
      default: break;
      }
      const Outcome one = run(c.mesh, o, 1);
      ASSERT_TRUE(one.report.ok) << one.report.message;
      ASSERT_EQ(vrs_test::check_run(c.mesh, one.mesh, o, one.report), "") << c.name;
      EXPECT_LT(one.mesh.face_count(), c.mesh.face_count()) << c.name;
      for (int threads : vrs_test::compared_thread_counts())
        expect_same(one, run(c.mesh, o, threads),
                    c.name + " variant " + std::to_string(variant) + ", " +
                        std::to_string(threads) + " threads against 1");
    }
}

TEST(Threads, AMeshOfManyBlocksIsSetUpAndWrittenTheSameWhateverTheThreadCount) {
  // More vertices and faces than one block of the set-up's and the output's loops (65 536),
  // so that the threads share them out; the certified bound and the corners' sources are
  // gathered block by block too.
  const Mesh in = vrs_test::terrain(300);
  ASSERT_GT(in.vertex_count(), 65536u);
  Options o;
  o.target.ratio = 0.3;
  o.corner_sources = true;
  o.max_error = HUGE_VAL; // the bound tracked, not limiting (as --error-bound does)
  const Outcome one = run(in, o, 1);
  ASSERT_TRUE(one.report.ok) << one.report.message;
  ASSERT_EQ(vrs_test::check_run(in, one.mesh, o, one.report), "");
  EXPECT_GT(one.report.error_bound, 0);
  for (int threads : {2, 3}) {
    const Outcome other = run(in, o, threads);
    expect_same(one, other, std::to_string(threads) + " threads against 1");
    EXPECT_EQ(one.report.remap, other.report.remap);
    EXPECT_EQ(one.report.error_bound, other.report.error_bound);
  }
}

TEST(Threads, ABoundTrackedAlongCreasesIsTheSameRunEveryTime) {
  // A vertex on a crease is removed as two sides of a seam, bounded as one patch: the price's
  // bound term read the sides' bounds unset, and the run differed from one call to the next
  // (fandisk at 1 %: 128 to 12 870 faces).
  const std::string path = vrs_test::cgal_mesh("fandisk.off");
  if (path.empty()) GTEST_FAIL() << "fandisk.off missing: run scripts/setup.sh";
  const Mesh in = vrs_test::read_off(path);
  Options o;
  o.target.ratio = 0.01;
  o.feature_angle_deg = 30;
  o.max_error = HUGE_VAL;
  const Outcome one = run(in, o, 1);
  ASSERT_TRUE(one.report.ok) << one.report.message;
  ASSERT_EQ(vrs_test::check_run(in, one.mesh, o, one.report), "");
  for (int threads : {1, 2, 3, 2}) {
    const Outcome other = run(in, o, threads);
    expect_same(one, other, std::to_string(threads) + " threads against 1");
    EXPECT_EQ(one.report.error_bound, other.report.error_bound);
  }
}

TEST(Threads, CancellingStopsAtTheSameRemovalWhateverTheThreadCount) {
  const Mesh in = vrs_test::icosphere(5);
  std::vector<Mesh> outs;
  for (int threads : {1, 2}) {
    Options o;
    o.target.ratio = 0.05;
    o.threads = threads;
    int calls = 0;
    o.progress = [&](float) { return ++calls < 4; };
    Mesh m = in;
    Report r = simplify(m, o);
    ASSERT_EQ(r.stop, StopReason::Cancelled);
    ASSERT_EQ(vrs_test::check_valid(in, m, r), "");
    outs.push_back(m);
  }
  EXPECT_TRUE(vrs_test::same_bits(outs[0], outs[1]));
}

TEST(Threads, ABadCountIsRefusedAndTheMeshLeftAlone) {
  const Mesh in = vrs_test::icosphere(2);
  for (int threads : {-1, 5000}) {
    Mesh m = in;
    Options o;
    o.threads = threads;
    Report r = simplify(m, o);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.message.find("threads"), std::string::npos) << r.message;
    EXPECT_TRUE(vrs_test::same_bits(in, m));
  }
}

// Small meshes are priced at once (Tuning::lazy_from_faces): the default run is the eager
// one below the size and the lazy one from it on.
TEST(Reevaluation, SmallMeshesArePricedAtOnceLargeOnesWhenPopped) {
  const Mesh in = vrs_test::icosphere(4); // 5120 faces
  auto run_with = [&](bool lazy, size_t lazy_from) {
    Options o;
    o.target.ratio = 0.1;
    o.tuning.lazy_reevaluation = lazy;
    o.tuning.lazy_from_faces = lazy_from;
    Mesh m = in;
    const Report r = simplify(m, o);
    EXPECT_EQ(vrs_test::check_run(in, m, o, r), "");
    return m;
  };
  const Mesh lazy = run_with(true, 0), eager = run_with(false, 0);
  ASSERT_FALSE(vrs_test::same_bits(lazy, eager)); // else this test tells nothing
  EXPECT_TRUE(vrs_test::same_bits(run_with(true, Tuning().lazy_from_faces), eager));
  EXPECT_TRUE(vrs_test::same_bits(run_with(true, in.face_count() + 1), eager));
  EXPECT_TRUE(vrs_test::same_bits(run_with(true, in.face_count()), lazy));
}

TEST(Reevaluation, LazyAndEagerBothKeepEveryInvariantAndReachTheTarget) {
  for (const char* name : {"elephant", "fandisk", "bunny00"}) {
    const std::string path = vrs_test::cgal_mesh(std::string(name) + ".off");
    ASSERT_FALSE(path.empty()) << "CGAL's data set is missing";
    const Mesh in = vrs_test::read_off(path);
    for (bool lazy : {true, false})
      for (double ratio : {0.5, 0.1}) {
        Options o;
        o.target.ratio = ratio;
        o.tuning.lazy_reevaluation = lazy;
        o.tuning.lazy_from_faces = 0; // lazy means lazy here, whatever the size
        Mesh m = in;
        Report r = simplify(m, o);
        ASSERT_EQ(vrs_test::check_run(in, m, o, r), "") << name << (lazy ? " lazy" : " eager");
        EXPECT_TRUE(r.target_reached) << name << (lazy ? " lazy " : " eager ") << ratio;
      }
  }
}
