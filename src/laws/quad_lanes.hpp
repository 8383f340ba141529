#pragma once
// Four doubles side by side, one a contact point, and 3-D vectors of them: two boxes touching face
// to face touch at four points, and the 3-D law takes the four at once (laws/contact_law_3d.hpp,
// four_point_law) where the processor has AVX2, whose 32-byte operations (AVX's) serve four points
// as SSE2's 16-byte ones (laws/double_lanes.hpp) serve two, with three operands (no register copy
// to keep a source); AVX2 rather than AVX alone for its broadcast of a register in one instruction
// (AVX takes two: a pair's motion, made in scalars, is broadcast into eleven vectors). Built only
// where GCC builds for x86-64 ELF (BLOCKDEM_QUAD_LANES); every function here is compiled for AVX2
// and inlined into a caller compiled for AVX2 (world/step_3d.cpp picks that caller at run time,
// quad_lanes_usable), so the rest of the program stays plain x86-64. Each lane rounds as the scalar
// expression written the same way (no fused multiply-add: that is FMA's, not enabled), so a lane's
// result is its point's own, as in two lanes.
#include <cstddef>
#include <cstring>

#include "laws/double_lanes.hpp"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__)
#define BLOCKDEM_QUAD_LANES 1
#else
#define BLOCKDEM_QUAD_LANES 0
#endif

namespace blockdem {

#if BLOCKDEM_QUAD_LANES

/// Whether this processor and its operating system run AVX2 (GCC's check includes the OS's saving of
/// the 32-byte registers).
inline bool quad_lanes_usable() { return __builtin_cpu_supports("avx2"); }

// For a function of four lanes: compiled for AVX2. Not always_inline: a caller compiled for plain
// x86-64 that is itself always inlined into an AVX2 one (world/step_3d.cpp's pair_law) may not take
// it in its own body; the AVX2 caller takes the whole by gnu::flatten.
#define BLOCKDEM_QUAD [[gnu::target("avx2")]] inline

using QuadLanes = double __attribute__((vector_size(32)));  ///< four doubles, one a point
using QuadMask = long long __attribute__((vector_size(32)));  ///< all bits set in a lane where true

struct Vec3Quad {
    QuadLanes x, y, z;
};

BLOCKDEM_QUAD QuadLanes quad(double value) { return QuadLanes{value, value, value, value}; }
BLOCKDEM_QUAD QuadLanes quad(double a, double b, double c, double d) { return QuadLanes{a, b, c, d}; }
BLOCKDEM_QUAD QuadLanes select(QuadMask where, QuadLanes yes, QuadLanes no) { return where ? yes : no; }
/// std::max(a, b) in each lane, as lane_max: (b > a) ? b : a, one vmaxpd.
BLOCKDEM_QUAD QuadLanes quad_max(QuadLanes a, QuadLanes b) { return __builtin_ia32_maxpd256(b, a); }
BLOCKDEM_QUAD QuadLanes quad_sqrt(QuadLanes a) { return __builtin_ia32_sqrtpd256(a); }
/// Whether the mask holds in all four lanes.
BLOCKDEM_QUAD bool all_four(QuadMask m) { return __builtin_ia32_movmskpd256(QuadLanes(m)) == 15; }
/// Lanes 0 and 1, and lanes 2 and 3, as two-lane vectors.
BLOCKDEM_QUAD DoubleLanes low_half(QuadLanes a) { return __builtin_ia32_vextractf128_pd256(a, 0); }
BLOCKDEM_QUAD DoubleLanes high_half(QuadLanes a) { return __builtin_ia32_vextractf128_pd256(a, 1); }

BLOCKDEM_QUAD Vec3Lanes low_half(const Vec3Quad& a) { return {low_half(a.x), low_half(a.y), low_half(a.z)}; }
BLOCKDEM_QUAD Vec3Lanes high_half(const Vec3Quad& a) { return {high_half(a.x), high_half(a.y), high_half(a.z)}; }

/// Four points' vectors, one a lane. x and y of each are read as one 16-byte pair and the four
/// pairs transposed ({x_a, y_a, x_c, y_c} and {x_b, y_b, x_d, y_d}, then their low and high
/// elements): 6 instructions for the two vectors, where element by element they took 10.
BLOCKDEM_QUAD Vec3Quad quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const auto xy = [](const Vec3& v) { return DoubleLanes{v.x, v.y}; };
    const QuadLanes ac = __builtin_ia32_vinsertf128_pd256(__builtin_ia32_pd256_pd(xy(a)), xy(c), 1);
    const QuadLanes bd = __builtin_ia32_vinsertf128_pd256(__builtin_ia32_pd256_pd(xy(b)), xy(d), 1);
    return {__builtin_ia32_unpcklpd256(ac, bd), __builtin_ia32_unpckhpd256(ac, bd), QuadLanes{a.z, b.z, c.z, d.z}};
}
BLOCKDEM_QUAD Vec3Quad quad(Vec3 value) { return {quad(value.x), quad(value.y), quad(value.z)}; }
BLOCKDEM_QUAD Vec3 lane(const Vec3Quad& v, int i) { return {v.x[i], v.y[i], v.z[i]}; }

BLOCKDEM_QUAD Vec3Quad operator+(const Vec3Quad& a, const Vec3Quad& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
BLOCKDEM_QUAD Vec3Quad operator-(const Vec3Quad& a, const Vec3Quad& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
BLOCKDEM_QUAD Vec3Quad operator*(QuadLanes s, const Vec3Quad& a) { return {s * a.x, s * a.y, s * a.z}; }
BLOCKDEM_QUAD QuadLanes dot(const Vec3Quad& a, const Vec3Quad& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
BLOCKDEM_QUAD Vec3Quad cross(const Vec3Quad& a, const Vec3Quad& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// Two-lane sums s of a pair's points, taken two at a time, given four points' terms v at once:
/// s += lanes 0 and 1, then s += lanes 2 and 3, the two additions two_point_law's pairs of points
/// make, in their order (so the same bits).
BLOCKDEM_QUAD void add_halves(DoubleLanes& s, QuadLanes v) {
    s += low_half(v);
    s += high_half(v);
}
BLOCKDEM_QUAD void add_halves(Vec3Lanes& s, const Vec3Quad& v) {
    add_halves(s.x, v.x);
    add_halves(s.y, v.y);
    add_halves(s.z, v.z);
}

/// Two doubles side by side at one place, and at another, as one vector {low's, high's}.
BLOCKDEM_QUAD QuadLanes halves_at(const unsigned char* low, const unsigned char* high) {
    DoubleLanes first, second;
    std::memcpy(&first, low, sizeof first);
    std::memcpy(&second, high, sizeof second);
    return __builtin_ia32_vinsertf128_pd256(__builtin_ia32_pd256_pd(first), second, 1);
}

/// Four doubles side by side at each of four places a, b, c, d (a point's fields), transposed:
/// out[k] = {a_k, b_k, c_k, d_k}. Each 16-byte half read once (a load, or an insert from memory),
/// then four unpacks: 12 instructions for the four vectors, where read one by one they took 5 a
/// vector, or 6 for two by quad(Vec3 ...)'s pairs.
BLOCKDEM_QUAD void load_transposed(const unsigned char* a, const unsigned char* b, const unsigned char* c,
                                   const unsigned char* d, QuadLanes (&out)[4]) {
    constexpr std::size_t two = 2 * sizeof(double);
    const QuadLanes ac_first = halves_at(a, c);  // {a0, a1, c0, c1}
    const QuadLanes bd_first = halves_at(b, d);
    const QuadLanes ac_second = halves_at(a + two, c + two);  // {a2, a3, c2, c3}
    const QuadLanes bd_second = halves_at(b + two, d + two);
    out[0] = __builtin_ia32_unpcklpd256(ac_first, bd_first);
    out[1] = __builtin_ia32_unpckhpd256(ac_first, bd_first);
    out[2] = __builtin_ia32_unpcklpd256(ac_second, bd_second);
    out[3] = __builtin_ia32_unpckhpd256(ac_second, bd_second);
}

/// The four vectors' lanes transposed: out[i] = {a_i, b_i, c_i, d_i}, the four values of point i
/// side by side (four unpacks and four 128-bit swaps).
BLOCKDEM_QUAD void transpose(QuadLanes a, QuadLanes b, QuadLanes c, QuadLanes d, QuadLanes (&out)[4]) {
    const QuadLanes ab_even = __builtin_ia32_unpcklpd256(a, b);  // {a0, b0, a2, b2}
    const QuadLanes ab_odd = __builtin_ia32_unpckhpd256(a, b);   // {a1, b1, a3, b3}
    const QuadLanes cd_even = __builtin_ia32_unpcklpd256(c, d);
    const QuadLanes cd_odd = __builtin_ia32_unpckhpd256(c, d);
    out[0] = __builtin_ia32_vperm2f128_pd256(ab_even, cd_even, 0x20);
    out[1] = __builtin_ia32_vperm2f128_pd256(ab_odd, cd_odd, 0x20);
    out[2] = __builtin_ia32_vperm2f128_pd256(ab_even, cd_even, 0x31);
    out[3] = __builtin_ia32_vperm2f128_pd256(ab_odd, cd_odd, 0x31);
}

/// Four vectors each summed across its four lanes, returned as {sum a, sum b, sum c, sum d}: each
/// (v0 + v2) + (v1 + v3), as add_halves onto zero and then lane_sum add them (the same bits but for
/// the sign of a sum of zeros). Two 128-bit swaps and an add a pair of vectors, and one horizontal
/// add for the four: 7 instructions, where each vector's halves, its two lanes and the stores of
/// its sums took about 7 a vector.
BLOCKDEM_QUAD QuadLanes sums_across_lanes(QuadLanes a, QuadLanes b, QuadLanes c, QuadLanes d) {
    const QuadLanes ac = __builtin_ia32_vperm2f128_pd256(a, c, 0x20) + __builtin_ia32_vperm2f128_pd256(a, c, 0x31);
    const QuadLanes bd = __builtin_ia32_vperm2f128_pd256(b, d, 0x20) + __builtin_ia32_vperm2f128_pd256(b, d, 0x31);
    return __builtin_ia32_haddpd256(ac, bd);  // {ac0 + ac1, bd0 + bd1, ac2 + ac3, bd2 + bd3}
}
/// Two vectors each summed across its four lanes, {sum a, sum b}, as sums_across_lanes does.
BLOCKDEM_QUAD DoubleLanes sums_across_lanes(QuadLanes a, QuadLanes b) {
    const QuadLanes ab = __builtin_ia32_vperm2f128_pd256(a, b, 0x20) + __builtin_ia32_vperm2f128_pd256(a, b, 0x31);
    return __builtin_ia32_haddpd(low_half(ab), high_half(ab));
}

#else

inline bool quad_lanes_usable() { return false; }

#endif

}  // namespace blockdem
