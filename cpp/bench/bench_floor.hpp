#pragma once
// The arithmetic floor printed next to a benchmark's figure: the operations
// of the work a cycle must do, at one operation per vector lane per clock
// cycle, with the widest vectors the processor offers (those the library
// dispatches to) and the clock measured here. Memory, branches and the wait
// on one result before the next are left out, so no program reaches the
// floor; the ratio says how far above it a figure stands.
//
// The work is counted from the benchmark's own cycles (samples, poses, scored
// rollouts); the operations of one item are fixed below, each with what it
// counts.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "fgdwa/dtw.hpp"
#include "fgdwa/robot.hpp"

namespace fgdwa {
namespace bench {

// Operations of one item of work (double precision unless said).
// A rollout's pose from the one before: two multiplications and two additions
// (the heading's cosine and sine are shared by every speed).
inline constexpr double kPoseStepOps = 4;
// A lower bound from the distance field's table at a point: two subtractions
// and two multiplications into pieces, two truncations, the index (a
// multiplication and an addition), the read and the scaling.
inline constexpr double kTableBoundOps = 10;
// What the planner does with a pose's bound: against the margin, and against
// the least so far.
inline constexpr double kPoseTestOps = 2;
// A footprint's point placed at a pose: four multiplications and four additions.
inline constexpr double kPlacingOps = 8;
// A cover disc's bound: its centre placed, the table's bound there, less its
// radius, and the least so far.
inline constexpr double kCoverDiscOps = kPlacingOps + kTableBoundOps + 2;
// A point obstacle's squared distance to a pose and the least so far: two
// subtractions, two multiplications, an addition and a minimum.
inline constexpr double kPointDistanceOps = 6;
// One cell of the DTW (single precision): the distance (two subtractions, two
// multiplications, an addition and a square root), the least of the three
// cells before (two minima) and the sum.
inline constexpr double kDtwCellOps = 9;
// A lidar beam marked in the map: its end placed (two multiplications and two
// additions) and the end's cell (as a table bound's index).
inline constexpr double kBeamOps = 10;

// A rollout's pose: its step, its bound (a circle's from one table look-up, a
// polygon's from its cover discs') and the planner's tests.
inline double pose_operations(const Footprint& footprint) {
  const double bound =
      footprint.is_circle() ? kTableBoundOps : static_cast<double>(footprint.cover().size()) * kCoverDiscOps;
  return kPoseStepOps + bound + kPoseTestOps;
}

// One kind of work in a cycle: how many items, and the operations of each.
struct Work {
  std::string what;
  double items = 0;
  double operations = 0;  // per item
  bool single = false;    // single precision: twice the lanes
};

struct Machine {
  double clock_hz = 0;          // measured; 0 where it cannot be
  std::size_t vector_bytes = 0;  // the widest vectors the processor offers
};

// The core's clock while busy: a chain of dependent integer additions runs at
// one a cycle. Ten to a loop pass, so that where the loop lies in memory (one
// pass a cycle or two, by its alignment) does not set the pace. The fastest
// of three rounds, the core settled at its clock.
inline double measured_clock_hz() {
#if defined(__x86_64__) || defined(__aarch64__)
#if defined(__x86_64__)
#define FGDWA_BENCH_ADD "add $1, %0\n\t"
#else
#define FGDWA_BENCH_ADD "add %0, %0, #1\n\t"
#endif
  double best = 0;
  for (int round = 0; round < 3; ++round) {
    constexpr std::uint64_t kPasses = 10'000'000, kAddsPerPass = 10;
    std::uint64_t x = 0;
    const auto start = std::chrono::steady_clock::now();
    for (std::uint64_t i = 0; i < kPasses; ++i)
      asm volatile(FGDWA_BENCH_ADD FGDWA_BENCH_ADD FGDWA_BENCH_ADD FGDWA_BENCH_ADD FGDWA_BENCH_ADD FGDWA_BENCH_ADD
                       FGDWA_BENCH_ADD FGDWA_BENCH_ADD FGDWA_BENCH_ADD FGDWA_BENCH_ADD
                   : "+r"(x));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = std::max(best, static_cast<double>(kPasses * kAddsPerPass) / seconds);
  }
#undef FGDWA_BENCH_ADD
  return best;
#else
  return 0;
#endif
}

inline Machine measured_machine() { return Machine{measured_clock_hz(), dtw_vector_bytes()}; }

// Seconds of arithmetic the work takes at one operation per lane per cycle.
inline double floor_seconds(const std::vector<Work>& work, const Machine& machine) {
  double seconds = 0;
  for (const Work& w : work) {
    const double lanes = std::max(1.0, static_cast<double>(machine.vector_bytes) / (w.single ? 4.0 : 8.0));
    seconds += w.items * w.operations / (lanes * machine.clock_hz);
  }
  return seconds;
}

inline void print_floor_header(const Machine& machine) {
  std::printf("\nFloor: the work's arithmetic at one operation per lane per cycle, on %s (%zu-byte vectors: %zu double\n"
              "or %zu float lanes), the clock measured at %.2f GHz; memory, branches and latency left out\n",
              dtw_instruction_set(), machine.vector_bytes, machine.vector_bytes / 8, machine.vector_bytes / 4,
              machine.clock_hz / 1e9);
  std::printf("%-34s %10s %10s %7s %8s  %s\n", "figure", "measured", "floor", "ratio", "target", "work per cycle");
}

// One figure's line: measured and target in microseconds (target <= 0: none).
inline void print_floor(const std::string& figure, double measured_us, const std::vector<Work>& work,
                        double target_us, const Machine& machine) {
  std::string described;
  for (const Work& w : work) {
    char item[160];
    std::snprintf(item, sizeof item, "%s%.0f %s x %.0f%s", described.empty() ? "" : " + ", w.items, w.what.c_str(),
                  w.operations, w.single ? " (float)" : "");
    described += item;
  }
  char target[32] = "-";
  if (target_us > 0) std::snprintf(target, sizeof target, "%.0f us", target_us);
  if (!(machine.clock_hz > 0)) {
    std::printf("%-34s %7.1f us %10s %7s %8s  %s (no clock measured on this processor)\n", figure.c_str(), measured_us,
                "-", "-", target, described.c_str());
    return;
  }
  const double floor_us = 1e6 * floor_seconds(work, machine);
  std::printf("%-34s %7.1f us %7.2f us %6.0fx %8s  %s\n", figure.c_str(), measured_us, floor_us, measured_us / floor_us,
              target, described.c_str());
}

}  // namespace bench
}  // namespace fgdwa
