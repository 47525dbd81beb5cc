#pragma once
// FL_VECTOR_CLONES before a function with a loop over columns of numbers: GCC compiles the function
// for AVX-512 (x86-64-v4), AVX2 (x86-64-v3) and the baseline, and the loader picks the best one the
// CPU has (GCC's target_clones); every call in it is inlined (flatten), so the loop is one block that
// vectorizes. The files that use it are compiled with -ffp-contract=off, so no clone fuses a
// multiply and an add and every clone rounds as the baseline does, and with -fno-math-errno and
// -fno-trapping-math, so sqrt and both sides of a select vectorize (neither option changes a result).
// The sanitizer build compiles the baseline only, without flattening (as fit.cpp's FL_FLATTEN).
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__) && !defined(__SANITIZE_ADDRESS__)
#define FL_VECTOR_CLONES [[gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"), gnu::flatten]]
#else
#define FL_VECTOR_CLONES
#endif
