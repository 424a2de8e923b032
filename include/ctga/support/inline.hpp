// CTGA_ALWAYS_INLINE: for the functions between a user's call and an expression's straight-line
// code (evaluation, a program's assignments, the typed mechanics functions). A call boundary
// there costs a pointer array on the stack and loads through it, and GCC's heuristics stop
// inlining inside a large caller, calling one helper per term.
//
// CTGA_INLINE_LAMBDA, after a lambda's parameter list, does the same for a lambda: a tree pass's
// step per body (chains/runs.hpp), which GCC otherwise keeps as a function per joint type, called
// per body with the pass's arrays reloaded through its captures (RNEA of the legged tree 1.07× →
// 0.97× the hand-written code).
//
// CTGA_SCALAR_CODE, before a function: GCC compiles it without its vectorisers, for straight-line
// code whose operands they would pair only by shuffling them into vector registers, more shuffles
// than the pairs save (articulated_inertia's transform: 76 shuffles among its 576 instructions;
// scalar, 552 instructions and ABA of the legged tree 1.02× → 0.99× the hand-written code).
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define CTGA_ALWAYS_INLINE [[gnu::always_inline]] inline
#define CTGA_INLINE_LAMBDA __attribute__((always_inline))
#else
#define CTGA_ALWAYS_INLINE inline
#define CTGA_INLINE_LAMBDA
#endif

#if defined(__GNUC__) && !defined(__clang__)
#define CTGA_SCALAR_CODE [[gnu::optimize("no-tree-vectorize")]]
#else
#define CTGA_SCALAR_CODE
#endif
