#pragma once
// Code-generation attributes of the hot loops. Both are off under AddressSanitizer, where
// flattened, instrumented functions take GCC many minutes to compile with debug information; the
// sanitizer build runs the same arithmetic, unflattened and for the baseline only.

// FL_FLATTEN before a function: every call in it is inlined (GCC's flatten), e.g. the small
// Jet-lane loops of Eigen that the compiler otherwise leaves as calls (about a tenth of a model
// fit's time).
//
// FL_VECTOR_CLONES before a function with a loop over columns of numbers: GCC compiles the function
// for AVX-512 (x86-64-v4), AVX2 (x86-64-v3) and the baseline, and the loader picks the best one the
// CPU has (GCC's target_clones); it is flattened too, so the loop is one block that vectorizes. The
// files that use it are compiled with -ffp-contract=off, so no clone fuses a multiply and an add
// and every clone rounds as the baseline does, and with -fno-math-errno and -fno-trapping-math, so
// sqrt and both sides of a select vectorize (neither option changes a result).
#if defined(__SANITIZE_ADDRESS__)
#define FL_FLATTEN
#define FL_VECTOR_CLONES
#elif defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
#define FL_FLATTEN [[gnu::flatten]]
#define FL_VECTOR_CLONES \
  [[gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"), gnu::flatten]]
#else
#define FL_FLATTEN [[gnu::flatten]]
#define FL_VECTOR_CLONES
#endif
