#pragma once
// Code-generation attribute of the hot loops. Off under AddressSanitizer, where flattened,
// instrumented functions take GCC many minutes to compile with debug information; the sanitizer
// build runs the same arithmetic, unflattened.
//
// FL_FLATTEN before a function: every call in it is inlined (GCC's flatten), e.g. the small
// Jet-lane loops of Eigen that the compiler otherwise leaves as calls (about a tenth of a model
// fit's time), and a loop over columns of numbers becomes one block that vectorizes. Every hot loop
// is compiled once, for the baseline x86-64 instruction set, so it runs the same instructions and
// gives the same bits on every CPU (per-CPU clones, AVX2 and AVX-512, bought under 5 % of CPU time
// on `lut ltc` and `reproduce`).
#if defined(__SANITIZE_ADDRESS__)
#define FL_FLATTEN
#elif defined(__GNUC__)
#define FL_FLATTEN [[gnu::flatten]]
#else
#define FL_FLATTEN
#endif
