#pragma once
// BLOCKDEM_VEX_CLONES: a function compiled twice, for the baseline x86-64 (SSE2) and for AVX, the
// one the processor has picked when the program loads (GCC and Clang's target_clones; an ifunc).
// Why: the build has no -march, so its arithmetic is SSE2's two-operand form, where an operation
// overwrites one of its inputs and the compiler copies every value still needed first (about a
// third of the 3-D step's per-body loops were such register copies); AVX's three-operand
// encoding of the same operations needs none. The same operations on the same operands, so the
// same bits: AVX alone brings no fused multiply-add (FMA is a target of its own, never named
// here), and contraction into one is off in the ISO C++ mode the project builds in. Elsewhere
// (another architecture, another compiler) it is empty: one baseline build, as before.
#if defined(__x86_64__) && defined(__ELF__) && (defined(__GNUC__) || defined(__clang__)) && !defined(BLOCKDEM_NO_CLONES)
#define BLOCKDEM_VEX_CLONES __attribute__((target_clones("avx", "default")))
#else
#define BLOCKDEM_VEX_CLONES
#endif
