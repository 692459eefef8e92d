// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Whole-frame fast path of the engine (docs/algorithm.md, section 11).
//
// Computes exactly what the block-by-block path of engine.cpp computes
// (census -> cost -> Eq. 3 -> Eq. 4 -> WTA), reorganised for a CPU:
//   - all disparities of a pixel are processed together, contiguous and
//     innermost, so one weight (the same for every d) multiplies a whole vector;
//   - the right census row is stored reversed and clamp-padded, so
//     cr(clamp(x - d), y) for d = 0..D-1 is one contiguous load;
//   - the census costs of the 32 rows y-15..y+16 live in a ring of per-row
//     [x][d] volumes; each row is computed once per band of output rows;
//   - weights are computed on the fly from the thresholds (7 comparisons),
//     never stored as planes;
//   - the WTA is fused: the horizontal sum is accumulated as E*64 + d, so the
//     unsigned minimum over d is the smallest E and, on a tie, the smallest d.
// Output rows are dealt to worker threads in bands; every pixel is a pure
// function of the inputs, so the result does not depend on the thread count.
//
// Two kernels implement the same arithmetic: an AVX2 one (compiled when the
// file is built with AVX2, see MCADSW_FAST_NATIVE in sw_ref/CMakeLists.txt) and
// a portable one in plain C++. Exactness of the AVX2 integer widths:
//   - vertical: vpmaddubsw multiplies cost (u8, 0..6) by weight (s8, 0..64) and
//     adds two taps: <= 768, no saturation; 16 such sums <= kVertCostMax < 2^15;
//   - horizontal: vpmaddwd multiplies Ev (< 2^15) by weight*64 (<= 4096) and
//     adds two taps in 32 bits; E*64 + d <= 1 511 522 367 < 2^31.
#include <algorithm>
#include <array>
#include <atomic>
#include <cstring>
#include <memory>
#include <mutex>
#include <thread>

#ifdef __AVX2__
#include <immintrin.h>
#endif

#include "mcadsw/ref.hpp"

namespace mcadsw {
namespace {

constexpr int kTaps = 2 * kRadius + 2;  // 32: the 31 taps plus one of weight 0, so taps pair up
constexpr int kPairs = kTaps / 2;       // 16
constexpr int kRing = 32;               // cost rows held: y-15 .. y+16 (tap 31 reads y+16)
constexpr int kBandRows = 32;           // output rows per work item
constexpr int kKeyShift = kDispBits;    // key = E << kDispBits | d (6 bits at DMAX = 64)
constexpr uint32_t kKeyD = (1u << kKeyShift) - 1;
// A padded disparity lane (d >= D) ends as kPadKey, above every real key (its
// sum may wrap; it is replaced after the sum).
constexpr uint32_t kPadKey = UINT32_MAX;
static_assert((uint64_t(kFinalCostMax) << kKeyShift) + kDmax - 1 < kPadKey, "keys of real d");
static_assert((int64_t(kVertCostMax) << kKeyShift) * 2 <= INT32_MAX, "vpmaddwd pair sum");
static_assert(kCostMax * kWeightMax * 2 <= INT16_MAX, "vpmaddubsw pair sum");
static_assert(kVertCostMax <= INT16_MAX, "Ev is a signed 16-bit vpmaddwd operand");

inline int clampi(int v, int n) { return v < 0 ? 0 : (v >= n ? n - 1 : v); }

// Frame-level inputs, built once and shared read-only by the workers.
struct Frame {
  int W = 0, H = 0, D = 0;
  int Dp = 0;  // D rounded up to a multiple of 16 (the SIMD lane count of costs)
  WeightTable table;
  WeightThresholds thr{};
  const uint8_t* left[3] = {};  // left Y, U, V planes, W*H each
  std::vector<uint8_t> cl;        // left census, W*H
  // Right census, each row reversed and clamp-padded: rrev[y][t] = cr(clamp(W-1-t), y),
  // t = 0..W+Dp-1, so cr(clamp(x-d), y) = rrev[y][W-1-x+d] for every d < Dp.
  std::vector<uint8_t> rrev;
  int rrev_stride = 0;
  // AVX2: left Y, U, V transposed and clamp-padded: lt[c][x * lt_stride + kColPad + t] =
  // P_c(x, clamp(t)) for t = -kColPad .. H + kColPad - 1, so the vertical taps of a
  // column are contiguous (no per-band gather).
  std::vector<uint8_t> lt[3];
  int lt_stride = 0;
};
constexpr int kColPad = kTaps;  // >= R rows above, R + 1 below, plus a 32-byte load

// Y, U, V of left column x, rows clamp(y_begin + t) for t = 0..n-1, into out[c][t].
void gather_column(const Frame& f, int x, int y_begin, int n, uint8_t* const* out) {
  for (int t = 0; t < n; ++t) {
    const size_t i = size_t(clampi(y_begin + t, f.H)) * f.W + x;
    for (int c = 0; c < 3; ++c) out[c][t] = f.left[c][i];
  }
}

// Y, U, V of left row y, clamp-padded: out[c][t] = P_c(clamp(t - R), y) for
// t = 0..W+kTaps-1, so the horizontal taps of (x, y) are out[c][x..x+31].
void gather_row(const Frame& f, int y, uint8_t* const* out) {
  for (int c = 0; c < 3; ++c) {
    const uint8_t* src = f.left[c] + size_t(y) * f.W;
    std::fill(out[c], out[c] + kRadius, src[0]);
    std::copy(src, src + f.W, out[c] + kRadius);
    std::fill(out[c] + kRadius + f.W, out[c] + f.W + kTaps, src[f.W - 1]);
  }
}

// Census of a whole plane through a clamp-padded copy (same codes as census_code).
std::vector<uint8_t> census_plane(const Plane& p) {
  const int W = p.width, H = p.height, R = kCensusRadius, PW = W + 2 * R;
  std::vector<uint8_t> pad(size_t(PW) * (H + 2 * R));
  for (int y = 0; y < H + 2 * R; ++y) {
    const uint8_t* src = &p.px[size_t(clampi(y - R, H)) * W];
    uint8_t* dst = &pad[size_t(y) * PW];
    std::fill(dst, dst + R, src[0]);
    std::copy(src, src + W, dst + R);
    std::fill(dst + R + W, dst + PW, src[W - 1]);
  }
  std::vector<uint8_t> out(size_t(W) * H);
  for (int y = 0; y < H; ++y) {
    const uint8_t* c = &pad[size_t(y + R) * PW + R];
    uint8_t* o = &out[size_t(y) * W];
    for (int x = 0; x < W; ++x) o[x] = 0;
    for (const Offset& t : kCensusTaps) {
      const uint8_t* n = c + t.dy * PW + t.dx;
      for (int x = 0; x < W; ++x) o[x] = uint8_t(o[x] << 1) | uint8_t(n[x] <= c[x]);
    }
  }
  return out;
}

Frame make_frame(const YuvImage& left, const YuvImage& right, const Config& cfg) {
  Frame f;
  f.W = left.width();
  f.H = left.height();
  f.D = cfg.disparities;
  f.Dp = (f.D + 15) / 16 * 16;
  f.table = cfg.table;
  f.thr = weight_thresholds(cfg.table);
  const int W = f.W, H = f.H;
  const Plane* yuv[3] = {&left.y, &left.u, &left.v};
  for (int c = 0; c < 3; ++c) f.left[c] = yuv[c]->px.data();
  f.cl = census_plane(left.y);
  const std::vector<uint8_t> cr = census_plane(right.y);
  f.rrev_stride = W + f.Dp;
  f.rrev.resize(size_t(f.rrev_stride) * H);
  for (int y = 0; y < H; ++y) {
    const uint8_t* src = &cr[size_t(y) * W];
    uint8_t* dst = &f.rrev[size_t(y) * f.rrev_stride];
    std::reverse_copy(src, src + W, dst);
    std::fill(dst + W, dst + f.rrev_stride, src[0]);
  }
#ifdef __AVX2__
  f.lt_stride = H + 2 * kColPad;
  for (int c = 0; c < 3; ++c) {
    f.lt[c].resize(size_t(f.lt_stride) * W);
    uint8_t* dst = f.lt[c].data();
    for (int t = 0; t < f.lt_stride; ++t) {
      const uint8_t* src = f.left[c] + size_t(clampi(t - kColPad, H)) * W;
      for (int x = 0; x < W; ++x) dst[size_t(x) * f.lt_stride + t] = src[x];
    }
  }
#endif
  return f;
}

// Section 12.6 from the fused keys (E << kKeyShift | d) of every real d.
uint16_t subpixel_from_keys(const uint32_t* keys, int d, int D) {
  const auto cost = [&](int e) { return (e >= 0 && e < D) ? keys[e] >> kKeyShift : 0u; };
  return uint16_t(subpixel_value(d, D, cost(d - 1), cost(d), cost(d + 1)));
}

// Per-worker buffers.
struct Scratch {
  std::vector<uint8_t> ring;  // portable: kRing cost rows of W*Dp, [x][d]
  std::vector<uint8_t> pairs;  // AVX2: one column's cost rows, interleaved in pairs
  std::vector<uint16_t> ev;   // vertical costs: one row (portable), the band (AVX2)
  std::vector<uint32_t> hp;   // AVX2: one row of horizontal-pass inputs, (W + 2R)*Dp
  std::vector<uint8_t> wv;    // AVX2: vertical weights of one column of the band
  std::vector<int16_t> wh;    // AVX2: horizontal weights * 64 of one row
  std::vector<uint8_t> line;  // AVX2: Y, U, V of one clamp-padded row or column
};

// ---- Portable kernel --------------------------------------------------------------
// Plain C++, natural [x][d] layouts. Used without AVX2, and by the tests.

void popcount_row_portable(const Frame& f, int r, uint8_t* out) {
  const int W = f.W, Dp = f.Dp;
  const uint8_t* rr = &f.rrev[size_t(r) * f.rrev_stride];
  for (int x = 0; x < W; ++x) {
    const uint8_t l = f.cl[size_t(r) * W + x];
    const uint8_t* rx = rr + (W - 1 - x);
    for (int d = 0; d < Dp; ++d) out[size_t(x) * Dp + d] = uint8_t(census_cost(l, rx[d]));
  }
}

int colour_dist(const uint8_t* const* taps, const int* centre, int i) {
  int s = 0;
  for (int c = 0; c < 3; ++c) s += std::abs(int(taps[c][i]) - centre[c]);
  return s;
}

void band_portable(const Frame& f, int y0, int y1, Scratch& s, uint8_t* out, uint16_t* sub) {
  const int W = f.W, H = f.H, Dp = f.Dp, D = f.D;
  const size_t row_bytes = size_t(W) * Dp;
  s.ring.resize(kRing * row_bytes);
  s.ev.resize(row_bytes);
  std::vector<uint32_t> acc(Dp);
  std::vector<uint8_t> buf(3 * size_t(W + kTaps));
  uint8_t* const line[3] = {&buf[0], &buf[size_t(W + kTaps)], &buf[2 * size_t(W + kTaps)]};
  int next = std::max(0, y0 - kRadius);  // next cost row to compute
  for (int y = y0; y < y1; ++y) {
    for (; next <= std::min(H - 1, y + kRadius + 1); ++next)
      popcount_row_portable(f, next, &s.ring[(next % kRing) * row_bytes]);
    // Eq. 3 for every column of row y.
    for (int x = 0; x < W; ++x) {
      const int centre[3] = {f.left[0][size_t(y) * W + x], f.left[1][size_t(y) * W + x],
                             f.left[2][size_t(y) * W + x]};
      gather_column(f, x, y - kRadius, kWindow, line);
      const uint8_t* taps[3] = {line[0], line[1], line[2]};
      uint16_t* ev = &s.ev[size_t(x) * Dp];
      std::fill(ev, ev + Dp, 0);
      for (int k = 0; k < kWindow; ++k) {
        const int w = f.table[colour_dist(taps, centre, k)];
        if (w == 0) continue;
        const uint8_t* c = &s.ring[(clampi(y + k - kRadius, H) % kRing) * row_bytes + size_t(x) * Dp];
        for (int d = 0; d < Dp; ++d) ev[d] = uint16_t(ev[d] + c[d] * w);
      }
    }
    // Eq. 4 and the WTA.
    gather_row(f, y, line);
    for (int x = 0; x < W; ++x) {
      const int centre[3] = {f.left[0][size_t(y) * W + x], f.left[1][size_t(y) * W + x],
                             f.left[2][size_t(y) * W + x]};
      const uint8_t* taps[3] = {line[0] + x, line[1] + x, line[2] + x};
      for (int d = 0; d < Dp; ++d) acc[d] = uint32_t(d);
      for (int j = 0; j < kWindow; ++j) {
        const uint32_t w = uint32_t(f.table[colour_dist(taps, centre, j)]) << kKeyShift;
        if (w == 0) continue;
        const uint16_t* ev = &s.ev[size_t(clampi(x + j - kRadius, W)) * Dp];
        for (int d = 0; d < Dp; ++d) acc[d] += ev[d] * w;
      }
      for (int d = D; d < Dp; ++d) acc[d] = kPadKey;
      const int d = int(*std::min_element(acc.begin(), acc.end()) & kKeyD);
      out[size_t(y) * W + x] = uint8_t(d);
      if (sub) sub[size_t(y) * W + x] = subpixel_from_keys(acc.data(), d, D);
    }
  }
}

// ---- AVX2 kernel ---------------------------------------------------------------------
#ifdef __AVX2__

// Weight bytes of the 32 taps whose Y, U, V start at taps[c] (tap 31 forced to 0),
// against the centre colour; the weight table is applied as its thresholds:
// code = #{i : dC < thr[i]}, weight = code ? 2^(code-1) : 0.
struct WeightUnit {
  __m256i thr[kWeightThresholds];    // as 16-bit lanes
  __m256i thr8[kWeightThresholds];   // as 8-bit lanes, when `bytes`
  bool bytes = true;                 // every threshold <= 255
  __m256i lut;   // code -> weight, in both 128-bit lanes
  __m256i last;  // zeroes byte 31

  explicit WeightUnit(const WeightThresholds& t) {
    for (int i = 0; i < kWeightThresholds; ++i) {
      thr[i] = _mm256_set1_epi16(int16_t(t[i]));
      thr8[i] = _mm256_set1_epi8(char(uint8_t(t[i])));
      bytes = bytes && t[i] <= 255;
    }
    lut = _mm256_setr_epi8(0, 1, 2, 4, 8, 16, 32, 64, 0, 0, 0, 0, 0, 0, 0, 0,  //
                           0, 1, 2, 4, 8, 16, 32, 64, 0, 0, 0, 0, 0, 0, 0, 0);
    last = _mm256_setr_epi8(-1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,  //
                            -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0);
  }

  __m256i weights(const uint8_t* const* taps, const uint8_t* centre) const {
    if (bytes) {
      // dC saturated at 255 compares with a threshold <= 255 as dC does.
      __m256i dc = _mm256_setzero_si256();
      for (int c = 0; c < 3; ++c) {
        const __m256i v = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(taps[c]));
        const __m256i m = _mm256_set1_epi8(char(centre[c]));
        dc = _mm256_adds_epu8(dc, _mm256_or_si256(_mm256_subs_epu8(v, m), _mm256_subs_epu8(m, v)));
      }
      __m256i code = _mm256_set1_epi8(kWeightThresholds);
      for (int i = 0; i < kWeightThresholds; ++i)  // -1 where dC >= thr[i]
        code = _mm256_add_epi8(code, _mm256_cmpeq_epi8(_mm256_max_epu8(dc, thr8[i]), dc));
      return _mm256_and_si256(_mm256_shuffle_epi8(lut, code), last);
    }
    __m256i lo = _mm256_setzero_si256(), hi = _mm256_setzero_si256();
    for (int c = 0; c < 3; ++c) {
      const __m256i v = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(taps[c]));
      const __m256i m = _mm256_set1_epi8(char(centre[c]));
      const __m256i ad = _mm256_or_si256(_mm256_subs_epu8(v, m), _mm256_subs_epu8(m, v));
      lo = _mm256_add_epi16(lo, _mm256_cvtepu8_epi16(_mm256_castsi256_si128(ad)));
      hi = _mm256_add_epi16(hi, _mm256_cvtepu8_epi16(_mm256_extracti128_si256(ad, 1)));
    }
    __m256i clo = _mm256_setzero_si256(), chi = _mm256_setzero_si256();
    for (int i = 0; i < kWeightThresholds; ++i) {  // each compare is -1 where dC < thr[i]
      clo = _mm256_sub_epi16(clo, _mm256_cmpgt_epi16(thr[i], lo));
      chi = _mm256_sub_epi16(chi, _mm256_cmpgt_epi16(thr[i], hi));
    }
    const __m256i code = _mm256_permute4x64_epi64(_mm256_packus_epi16(clo, chi), 0xD8);
    return _mm256_and_si256(_mm256_shuffle_epi8(lut, code), last);
  }
};

// acc += the multiply-add of 32 bytes at p with w, as one vpmaddwd / vpmaddubsw
// with a memory operand and one add into acc. Written in asm because GCC 12
// otherwise copies every accumulator each step (or spills the products).
inline void madd_add_epi32(__m256i& acc, const void* p, __m256i w) {
  __m256i t;
  asm("vpmaddwd %2, %3, %1\n\tvpaddd %1, %0, %0"
      : "+x"(acc), "=&x"(t)
      : "m"(*static_cast<const __m256i*>(p)), "x"(w));
}
// vpmaddubsw multiplies unsigned bytes of its first source by signed bytes of the
// second; here the weights (0..64) are the first and the costs (0..6) the second,
// which is the same product since both fit in 7 bits.
inline void maddubs_add_epi16(__m256i& acc, const void* p, __m256i w) {
  __m256i t;
  asm("vpmaddubsw %2, %3, %1\n\tvpaddw %1, %0, %0"
      : "+x"(acc), "=&x"(t)
      : "m"(*static_cast<const __m256i*>(p)), "x"(w));
}

// Census costs of column x at rows clamp(y_begin + v), v = 0..n-1, interleaved in
// pairs of consecutive rows for vpmaddubsw: pairs + v * 2 * Dp holds, for v = 0..n-2,
// per 32-d chunk vpunpcklbw then vpunpckhbw of rows v and v+1, each row's chunk taken
// in the order d 0-7, 16-23, 8-15, 24-31 (qwords 0, 2, 1, 3), so the 16-bit pair
// sums come out as d 0-15 and 16-31 in order; a 16-d tail chunk is taken in order.
template <int Dp>
void cost_pairs_avx2(const Frame& f, int x, int y_begin, int n, uint8_t* pairs) {
  constexpr int kChunks = Dp / 32;
  constexpr bool kTail = Dp % 32 != 0;
  const int W = f.W, H = f.H;
  const __m256i nib = _mm256_set1_epi8(0x0F);
  const __m256i pc = _mm256_setr_epi8(0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4,  //
                                      0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4);
  const auto popcount = [&](__m256i v) {
    const __m256i lo = _mm256_and_si256(v, nib);
    const __m256i hi = _mm256_and_si256(_mm256_srli_epi16(v, 4), nib);
    return _mm256_add_epi8(_mm256_shuffle_epi8(pc, lo), _mm256_shuffle_epi8(pc, hi));
  };
  __m256i prev[kChunks + 1] = {}, cur[kChunks + 1] = {};
  for (int v = 0; v < n; ++v) {
    const int r = clampi(y_begin + v, H);
    const uint8_t* rx = &f.rrev[size_t(r) * f.rrev_stride + (W - 1 - x)];
    const __m256i l = _mm256_set1_epi8(char(f.cl[size_t(r) * W + x]));
    for (int c = 0; c < kChunks; ++c) {
      const __m256i cr = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(rx + 32 * c));
      cur[c] = _mm256_permute4x64_epi64(popcount(_mm256_xor_si256(cr, l)), 0xD8);
    }
    if constexpr (kTail) {
      const __m128i cr = _mm_loadu_si128(reinterpret_cast<const __m128i*>(rx + 32 * kChunks));
      cur[kChunks] = popcount(_mm256_castsi128_si256(_mm_xor_si128(cr, _mm256_castsi256_si128(l))));
    }
    if (v > 0) {
      uint8_t* o = pairs + size_t(v - 1) * 2 * Dp;
      for (int c = 0; c < kChunks; ++c) {
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(o + 64 * c), _mm256_unpacklo_epi8(prev[c], cur[c]));
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(o + 64 * c + 32), _mm256_unpackhi_epi8(prev[c], cur[c]));
      }
      if constexpr (kTail) {
        const __m128i a = _mm256_castsi256_si128(prev[kChunks]), b = _mm256_castsi256_si128(cur[kChunks]);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(o + 64 * kChunks), _mm_unpacklo_epi8(a, b));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(o + 64 * kChunks + 16), _mm_unpackhi_epi8(a, b));
      }
    }
    for (int c = 0; c < kChunks + int(kTail); ++c) prev[c] = cur[c];
  }
}

template <int Dp>
void band_avx2(const Frame& f, int y0, int y1, Scratch& s, uint8_t* out, uint16_t* sub) {
  constexpr int kChunks = Dp / 32;           // full 32-d cost chunks
  constexpr bool kTail = Dp % 32 != 0;       // one 16-d chunk after them
  constexpr int kEvVecs = Dp / 16;           // Ev: 16 d per vector
  constexpr int kKeyVecs = Dp / 8;           // keys: 8 d per vector
  const int W = f.W, B = y1 - y0;
  const int rows = B + kTaps - 1;  // cost rows y0-R .. y1+R (clamped), v = 0..rows-1
  const size_t pair_bytes = 2 * size_t(Dp);
  s.pairs.resize(size_t(rows - 1) * pair_bytes);
  uint8_t* const pairs = s.pairs.data();
  s.ev.resize(size_t(B) * W * Dp);
  s.hp.resize(size_t(W + 2 * kRadius) * Dp);
  s.wh.resize(size_t(W) * kTaps);
  s.wv.resize(size_t(B) * kTaps);
  const size_t line_len = size_t(W + kTaps);
  s.line.resize(3 * line_len);
  uint8_t* const line[3] = {&s.line[0], &s.line[line_len], &s.line[2 * line_len]};
  const WeightUnit wu(f.thr);
  __m256i key0[kKeyVecs];  // d
  __m256i pad[kKeyVecs];   // all ones in the padded lanes (d >= D)
  for (int a = 0; a < kKeyVecs; ++a) {
    alignas(32) uint32_t k[8], p[8];
    for (int i = 0; i < 8; ++i) {
      k[i] = uint32_t(8 * a + i);
      p[i] = 8 * a + i < f.D ? 0 : kPadKey;
    }
    key0[a] = _mm256_load_si256(reinterpret_cast<const __m256i*>(k));
    pad[a] = _mm256_load_si256(reinterpret_cast<const __m256i*>(p));
  }

  // Eq. 3, column by column: Ev of (x, y0..y1-1), two taps per vpmaddubsw.
  // Stored per 16 d in the order d 0-3, 8-11, 4-7, 12-15 for the vpunpck*wd below.
  for (int x = 0; x < W; ++x) {
    // The column's cost rows, already interleaved in pairs, stay in L1 for the band.
    cost_pairs_avx2<Dp>(f, x, y0 - kRadius, rows, pairs);
    const size_t col = size_t(x) * f.lt_stride + kColPad + (y0 - kRadius);
    const uint8_t* lt[3] = {&f.lt[0][col], &f.lt[1][col], &f.lt[2][col]};
    // The weights of the whole column first: reading them back right after the
    // vector store would stall on store forwarding.
    for (int yl = 0; yl < B; ++yl) {
      const uint8_t* taps[3] = {lt[0] + yl, lt[1] + yl, lt[2] + yl};
      const uint8_t cx[3] = {taps[0][kRadius], taps[1][kRadius], taps[2][kRadius]};
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(&s.wv[size_t(yl) * kTaps]), wu.weights(taps, cx));
    }
    for (int yl = 0; yl < B; ++yl) {
      const uint8_t* wv = &s.wv[size_t(yl) * kTaps];
      __m256i acc[2 * kChunks + 1];
      for (auto& a : acc) a = _mm256_setzero_si256();
      __m128i tlo = _mm_setzero_si128(), thi = _mm_setzero_si128();
      const uint8_t* p = pairs + size_t(yl) * pair_bytes;  // pair i: rows yl+2i, yl+2i+1
#pragma GCC unroll 4
      for (int i = 0; i < kPairs; ++i, p += 2 * pair_bytes) {
        int16_t pair;
        std::memcpy(&pair, &wv[2 * i], 2);
        const __m256i w = _mm256_set1_epi16(pair);
        for (int c = 0; c < kChunks; ++c) {
          maddubs_add_epi16(acc[2 * c], p + 64 * c, w);
          maddubs_add_epi16(acc[2 * c + 1], p + 64 * c + 32, w);
        }
        if constexpr (kTail) {
          const __m128i lo = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + 64 * kChunks));
          const __m128i hi = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + 64 * kChunks + 16));
          const __m128i w128 = _mm256_castsi256_si128(w);
          tlo = _mm_add_epi16(tlo, _mm_maddubs_epi16(lo, w128));
          thi = _mm_add_epi16(thi, _mm_maddubs_epi16(hi, w128));
        }
      }
      if constexpr (kTail) acc[2 * kChunks] = _mm256_set_m128i(thi, tlo);
      uint16_t* ev = &s.ev[(size_t(yl) * W + x) * Dp];
      for (int v = 0; v < kEvVecs; ++v)
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(ev + 16 * v),
                            _mm256_permute4x64_epi64(acc[v], 0xD8));
    }
  }

  for (int yl = 0; yl < B; ++yl) {
    const int y = y0 + yl;
    const uint16_t* evrow = &s.ev[size_t(yl) * W * Dp];
    // Horizontal-pass inputs: hp[x'+R] = (Ev(clamp(x'), d), Ev(clamp(x'+1), d)) as
    // 16-bit pairs, d in order, for x' = -R .. W+R-1.
    for (int xp = -kRadius; xp < W + kRadius; ++xp) {
      const uint16_t* e0 = evrow + size_t(clampi(xp, W)) * Dp;
      const uint16_t* e1 = evrow + size_t(clampi(xp + 1, W)) * Dp;
      uint32_t* h = &s.hp[size_t(xp + kRadius) * Dp];
      for (int v = 0; v < kEvVecs; ++v) {
        const __m256i a = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(e0 + 16 * v));
        const __m256i b = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(e1 + 16 * v));
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(h + 16 * v), _mm256_unpacklo_epi16(a, b));
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(h + 16 * v + 8), _mm256_unpackhi_epi16(a, b));
      }
    }

    // Horizontal weights of the row, scaled by 64, as 16-bit (tap 2i, tap 2i+1) pairs.
    gather_row(f, y, line);
    for (int x = 0; x < W; ++x) {
      const uint8_t* taps[3] = {line[0] + x, line[1] + x, line[2] + x};
      const size_t centre = size_t(y) * W + x;
      const uint8_t cx[3] = {f.left[0][centre], f.left[1][centre], f.left[2][centre]};
      const __m256i wb = wu.weights(taps, cx);
      int16_t* wh = &s.wh[size_t(x) * kTaps];
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(wh),
                          _mm256_slli_epi16(_mm256_cvtepu8_epi16(_mm256_castsi256_si128(wb)), kKeyShift));
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(wh + 16),
                          _mm256_slli_epi16(_mm256_cvtepu8_epi16(_mm256_extracti128_si256(wb, 1)), kKeyShift));
    }

    // Eq. 4 fused with the WTA, two taps per vpmaddwd.
    const uint32_t* hp = s.hp.data();
    for (int x = 0; x < W; ++x) {
      const int16_t* wh = &s.wh[size_t(x) * kTaps];
      __m256i acc[kKeyVecs];
      for (int a = 0; a < kKeyVecs; ++a) acc[a] = key0[a];
#pragma GCC unroll 4
      for (int i = 0; i < kPairs; ++i) {
        int32_t pair;
        std::memcpy(&pair, &wh[2 * i], 4);
        const __m256i w = _mm256_set1_epi32(pair);
        const uint32_t* h = hp + size_t(x + 2 * i) * Dp;  // x' = x - R + 2i
        for (int a = 0; a < kKeyVecs; ++a) madd_add_epi32(acc[a], h + 8 * a, w);
      }
      for (int a = 0; a < kKeyVecs; ++a) acc[a] = _mm256_or_si256(acc[a], pad[a]);
      __m256i m = acc[0];
      for (int a = 1; a < kKeyVecs; ++a) m = _mm256_min_epu32(m, acc[a]);
      __m128i m4 = _mm_min_epu32(_mm256_castsi256_si128(m), _mm256_extracti128_si256(m, 1));
      m4 = _mm_min_epu32(m4, _mm_shuffle_epi32(m4, 0x4E));
      m4 = _mm_min_epu32(m4, _mm_shuffle_epi32(m4, 0xB1));
      const int d = int(uint32_t(_mm_cvtsi128_si32(m4)) & kKeyD);
      out[size_t(y) * W + x] = uint8_t(d);
      if (sub) {
        alignas(32) uint32_t keys[Dp];
        for (int a = 0; a < kKeyVecs; ++a)
          _mm256_store_si256(reinterpret_cast<__m256i*>(keys + 8 * a), acc[a]);
        sub[size_t(y) * W + x] = subpixel_from_keys(keys, d, f.D);
      }
    }
  }
}

#endif  // __AVX2__

// Worker buffers are kept between calls (a few MB at most), so repeated calls
// do not pay for allocating and faulting in fresh pages.
std::mutex scratch_mutex;
std::vector<std::unique_ptr<Scratch>> scratch_pool;

std::unique_ptr<Scratch> take_scratch() {
  {
    const std::lock_guard<std::mutex> lock(scratch_mutex);
    if (!scratch_pool.empty()) {
      std::unique_ptr<Scratch> s = std::move(scratch_pool.back());
      scratch_pool.pop_back();
      return s;
    }
  }
  return std::make_unique<Scratch>();
}

void return_scratch(std::unique_ptr<Scratch> s) {
  const std::lock_guard<std::mutex> lock(scratch_mutex);
  if (scratch_pool.size() < std::max(4u, std::thread::hardware_concurrency()))
    scratch_pool.push_back(std::move(s));
}

using BandFn = void (*)(const Frame&, int, int, Scratch&, uint8_t*, uint16_t*);

BandFn pick_kernel(int Dp, bool portable) {
#ifdef __AVX2__
  if (!portable) switch (Dp) {
      case 16: return band_avx2<16>;
      case 32: return band_avx2<32>;
      case 48: return band_avx2<48>;
      case 64: return band_avx2<64>;
      case 80: return band_avx2<80>;  // 80 .. 128: builds with DMAX above 64 (MCADSW_DMAX)
      case 96: return band_avx2<96>;
      case 112: return band_avx2<112>;
      case 128: return band_avx2<128>;
      default: break;
    }
#else
  (void)Dp;
  (void)portable;
#endif
  return band_portable;
}

static_assert(kDmax <= 128, "the AVX2 kernel is instantiated for Dp = 16..128");

}  // namespace

Plane disparity_map_fast(const YuvImage& left, const YuvImage& right, const Config& cfg,
                         bool portable, Plane16* subpixel) {
  check_views(left, right);
  check_config(cfg, left.width(), left.height());
  const Frame f = make_frame(left, right, cfg);
  const BandFn band = pick_kernel(f.Dp, portable);
  Plane disp(f.W, f.H);
  if (subpixel) *subpixel = Plane16(f.W, f.H);
  uint16_t* sub = subpixel ? subpixel->px.data() : nullptr;
  int workers = cfg.threads > 0 ? cfg.threads : int(std::thread::hardware_concurrency());
  workers = std::clamp(workers, 1, (f.H + kBandRows - 1) / kBandRows);
  // About kBandRows rows per band, and a multiple of `workers` bands so they
  // finish together. Bands are taken in order from a shared counter, so a
  // worker on a busy core takes fewer. No pixel depends on the band split.
  const int per_worker = (f.H + kBandRows * workers - 1) / (kBandRows * workers);
  const int rows = (f.H + per_worker * workers - 1) / (per_worker * workers);
  const int bands = (f.H + rows - 1) / rows;
  std::atomic<int> next_band{0};
  auto work = [&] {
    std::unique_ptr<Scratch> s = take_scratch();
    for (int b; (b = next_band.fetch_add(1)) < bands;)
      band(f, b * rows, std::min(f.H, (b + 1) * rows), *s, disp.px.data(), sub);
    return_scratch(std::move(s));
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (auto& th : pool) th.join();
  return disp;
}

}  // namespace mcadsw
