#pragma once
// Dynamic time warping between two planar point sequences (Eq. 10):
// steps (i-1, j), (i, j-1), (i-1, j-1), point distance the 2-D Euclidean
// distance, DTW the sum of point distances along the optimal warping path.
#include <cstddef>
#include <vector>

#include "fgdwa/geometry.hpp"

namespace fgdwa {

// Sakoe-Chiba band: cell (i, j) is allowed when j lies within `band` of the
// diagonal through (0, 0) and (n - 1, m - 1) at row i. A negative band means no
// band. A band too narrow to connect the corners is widened until it does.
constexpr int kNoBand = -1;

// Reusable buffers, so the control loop allocates nothing per call.
// Threads: one per thread (its buffers are written by every call); dtw()
// builds its own.
class SimilarityCritic;

class DtwWorkspace {
 public:
  double distance(const Vec2* a, std::size_t n, const Vec2* b, std::size_t m, int band = kNoBand);
  double distance(const std::vector<Vec2>& a, const std::vector<Vec2>& b, int band = kNoBand) {
    return distance(a.data(), a.size(), b.data(), b.size(), band);
  }

  // The full DTW (no band) of `count` sequences of n points each against b,
  // side by side so the compiler can vectorise across them: point i of
  // sequence k is (ax[i * count + k], ay[i * count + k]). Each result equals
  // distance() of that sequence, bit for bit.
  void distance_batch(const double* ax, const double* ay, std::size_t n, std::size_t count, const Vec2* b,
                      std::size_t m, double* out);

  // The same in single precision, vectorised with the widest instruction set
  // the processor has (dtw_instruction_set()). Every instruction set gives
  // the same bits. Keep coordinates small (relative to a nearby origin): a
  // float carries 7 digits.
  void distance_batch_f32(const float* ax, const float* ay, std::size_t n, std::size_t count, const float* bx,
                          const float* by, std::size_t m, float* out);

 private:
  // distance_batch_f32 without its entry checks, for the similarity critic,
  // whose rollouts come from a checked state: checking every coordinate of
  // every batch would cost it a fifth of the kernel.
  friend class SimilarityCritic;
  void distance_batch_f32_unchecked(const float* ax, const float* ay, std::size_t n, std::size_t count,
                                    const float* bx, const float* by, std::size_t m, float* out);

  std::vector<double> previous_, current_, bx_, by_, row_, left_;
  std::vector<float> rows_f32_;
};

// The instruction set distance_batch_f32 runs with on this processor ("AVX2",
// "NEON", ...).
const char* dtw_instruction_set();
// The bytes of its vectors (16 for SSE4 and NEON, 32 for AVX2, 64 for AVX-512).
std::size_t dtw_vector_bytes();

// One-off DTW; throws fgdwa::Error on an empty sequence or a non-finite point.
double dtw(const std::vector<Vec2>& a, const std::vector<Vec2>& b, int band = kNoBand);

}  // namespace fgdwa
