// Private to src/: STICKSLIP_KERNEL marks a hot numerical kernel (the seed
// law's Taylor recurrences). With GCC on x86-64 it is compiled twice, for the
// baseline and for x86-64-v3 (AVX2, FMA), and the loader picks the clone the
// CPU runs (function multiversioning, target_clones). The two clones' results
// differ by rounding (FMA contracts a * b + c). The CMake option
// STICKSLIP_KERNEL_CLONES=OFF builds the baseline only.
#pragma once

#include <cstddef>  // defines __GLIBC__ where glibc is the C library

// glibc (ifunc) and GCC 11+ (arch=x86-64-v3) only; elsewhere the baseline.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 11 && defined(__x86_64__) && \
    defined(__GLIBC__) && !defined(STICKSLIP_NO_KERNEL_CLONES)
#define STICKSLIP_KERNEL __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define STICKSLIP_KERNEL
#endif
