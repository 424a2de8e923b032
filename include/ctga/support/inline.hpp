// CTGA_ALWAYS_INLINE: for the functions between a user's call and an expression's straight-line
// code (evaluation, a program's assignments, the typed mechanics functions). A call boundary
// there costs a pointer array on the stack and loads through it, and GCC's heuristics stop
// inlining inside a large caller, calling one helper per term.
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define CTGA_ALWAYS_INLINE [[gnu::always_inline]] inline
#else
#define CTGA_ALWAYS_INLINE inline
#endif
