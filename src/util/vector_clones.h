/* RS_VECTOR_CLONES before a function whose loops over arrays vectorise: in a build for the
 * baseline x86-64 (the portable build: no -mavx2), GCC compiles it twice, for AVX2 and for
 * the baseline, and the dynamic loader picks the one the machine runs (an ifunc, once at
 * start-up). AVX2 without FMA, and ISO C contracts nothing: the operations, so the
 * results, are the same in both, only four doubles wide instead of two. A build for AVX2
 * already (REELSIM_SIMD) or another compiler or system has the function once. On static
 * functions only: GCC exports the ifunc and its resolver whatever visibility is asked for,
 * and the library exports its rs_ names alone (tests symbols.library, install.exports), so
 * a library function with such loops calls a static one that carries the clones. Private
 * to the library. */
#ifndef REELSIM_UTIL_VECTOR_CLONES_H
#define REELSIM_UTIL_VECTOR_CLONES_H

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && \
    !defined(__AVX2__)
#define RS_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define RS_VECTOR_CLONES
#endif

#endif
