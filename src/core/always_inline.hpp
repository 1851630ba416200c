#pragma once
/// @file always_inline.hpp
/// FSWEEP_ALWAYS_INLINE: inline this function (or lambda: written after its parameter list) at
/// every call, whatever the compiler's size heuristics say. Reserved for the innermost loops,
/// where a benchmark showed that the compiler's own choice differs between translation units and
/// costs time (grid_search.hpp's relaxation, and the same loop of bench/textbook_astar.hpp).
/// GCC and Clang; a no-op elsewhere.

#if defined(__GNUC__)
#define FSWEEP_ALWAYS_INLINE __attribute__((always_inline))
#else
#define FSWEEP_ALWAYS_INLINE
#endif
