#pragma once
// BLOCKDEM_VEX_CLONES: a function compiled twice, for the baseline x86-64 (SSE2) and for AVX, the
// one the processor has picked when the program loads (GCC and Clang's target_clones; an ifunc).
// Why: the build has no -march, so its arithmetic is SSE2's two-operand form, where an operation
// overwrites one of its inputs and the compiler copies every value still needed first (about a
// sixth of the 3-D step's per-body loops' instructions were such register copies); AVX's three-operand
// encoding of the same operations needs none. The same operations on the same operands, so the
// same bits: AVX brings no fused multiply-add (FMA is a target of its own, and must never be
// named here: GCC would then fuse a * b + c, which rounds once instead of twice). Elsewhere
// (another architecture, another compiler, Clang before 14) it is empty: one baseline build, as
// before; -DBLOCKDEM_NO_CLONES makes it empty too.
#if defined(__x86_64__) && defined(__ELF__) && defined(__GNUC__) && (!defined(__clang__) || __clang_major__ >= 14) && \
    !defined(BLOCKDEM_NO_CLONES)
#define BLOCKDEM_VEX_CLONES __attribute__((target_clones("avx", "default")))
#else
#define BLOCKDEM_VEX_CLONES
#endif
