// SPDX-License-Identifier: MIT
// SILODEM_HOT: force inlining of a small function of the force loop (contact kernels, geometry).
// GCC's size heuristics otherwise keep some kernels as calls, one per contact and kernel (the
// gain of inlining them: BENCHMARKS.md, "What the engine does to be fast").
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define SILODEM_HOT [[gnu::always_inline]] inline
#else
#define SILODEM_HOT inline
#endif
