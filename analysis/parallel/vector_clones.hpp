#pragma once
// SBPACK_VECTOR_CLONES marks a hot loop to be compiled twice, for AVX2 (x86-64-v3) and for any
// x86-64, the variant picked at run time (GCC's target_clones); nothing elsewhere.

#if defined(__GNUC__) && defined(__x86_64__)
#define SBPACK_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define SBPACK_VECTOR_CLONES
#endif
