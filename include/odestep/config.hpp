// SPDX-License-Identifier: BSL-1.0
// odestep: build configuration, the one place for the library's macros.
#ifndef ODESTEP_CONFIG_HPP
#define ODESTEP_CONFIG_HPP

/// \file
/// The macros every odestep header uses. Each may be defined by the user before the first odestep header
/// to override the choice made here (for a compiler the library does not know).

// Two unrolling macros, named for when they unroll. Each also keeps its name of before 0.2.0, deprecated
// (removed in 1.0.0): ODESTEP_UNROLL for ODESTEP_UNROLL_UNLESS_SIZE, ODESTEP_STEP_UNROLL for
// ODESTEP_STEP_UNROLL_ALWAYS. A user's definition of either name, old or new, sets both.

// Loops over the components of a state outside a step (whole-state operations, the C API's copies) are
// unrolled (fully, for up to 16 components) except where the build optimizes for size: there the loop is
// smaller, and flash is what counts.
#ifndef ODESTEP_UNROLL_UNLESS_SIZE
#if defined(ODESTEP_UNROLL)
#define ODESTEP_UNROLL_UNLESS_SIZE ODESTEP_UNROLL
#elif defined(__OPTIMIZE_SIZE__) || !(defined(__GNUC__) || defined(__clang__))
#define ODESTEP_UNROLL_UNLESS_SIZE
#else
#define ODESTEP_UNROLL_UNLESS_SIZE _Pragma("GCC unroll 16")
#endif
#endif
#ifndef ODESTEP_UNROLL
#define ODESTEP_UNROLL ODESTEP_UNROLL_UNLESS_SIZE
#endif

// The loops over the components inside one step of the explicit Runge-Kutta steppers, of the Adams methods
// and of the Newtonian ones (velocity Verlet, Beeman, the splittings) are unrolled at every optimization
// level, -Os included: unrolled and with the right-hand side inlined (ODESTEP_STEP_FLATTEN) the step is as
// fast as the same step written out by hand, where the rolled loop spills what is live across the calls of
// f. Define it empty (with ODESTEP_STEP_FLATTEN) for the rolled, smaller -Os code (docs/performance.md,
// "-Os", has the figures).
#ifndef ODESTEP_STEP_UNROLL_ALWAYS
#if defined(ODESTEP_STEP_UNROLL)
#define ODESTEP_STEP_UNROLL_ALWAYS ODESTEP_STEP_UNROLL
#elif defined(__GNUC__) || defined(__clang__)
#define ODESTEP_STEP_UNROLL_ALWAYS _Pragma("GCC unroll 16")
#else
#define ODESTEP_STEP_UNROLL_ALWAYS
#endif
#endif
#ifndef ODESTEP_STEP_UNROLL
#define ODESTEP_STEP_UNROLL ODESTEP_STEP_UNROLL_ALWAYS
#endif

// Where the build optimizes for size, those steps inline every call in them, the right-hand side's (the
// force's) included (GCC's and Clang's flatten), as the step written out by hand does: GCC at -Os otherwise
// calls a right-hand side used several times out of line, and every value live across the calls spills.
// The price is flash: the right-hand side is inlined once per evaluation. Define it empty to keep a large
// right-hand side out of line (less flash, more instructions). Other optimization levels inline the
// right-hand side by themselves.
#ifndef ODESTEP_STEP_FLATTEN
#if defined(__OPTIMIZE_SIZE__) && (defined(__GNUC__) || defined(__clang__))
#define ODESTEP_STEP_FLATTEN [[gnu::flatten]]
#else
#define ODESTEP_STEP_FLATTEN
#endif
#endif

// The stepper's per-component arithmetic is written as small functions over the table (one per weight row,
// class of terms, ...); they are expression fragments, meant to be inlined where they are used whatever
// the optimization level (at -Os a fragment used twice could otherwise stay a call inside the loop).
#ifndef ODESTEP_INLINE
#if defined(__GNUC__) || defined(__clang__)
#define ODESTEP_INLINE [[gnu::always_inline]] inline
#else
#define ODESTEP_INLINE inline
#endif
#endif

// A rare path (a multistep method's start, the event loop's crossings) kept out of line, so that the
// common step's frame and registers hold only what it needs.
#ifndef ODESTEP_NOINLINE
#if defined(__GNUC__) || defined(__clang__)
#define ODESTEP_NOINLINE [[gnu::noinline]]
#elif defined(_MSC_VER)
#define ODESTEP_NOINLINE __declspec(noinline)
#else
#define ODESTEP_NOINLINE
#endif
#endif

// A state that a step updates in place through a reference the compiler cannot prove distinct from the
// step's other states (the unchecked Newtonian steps' x, v and kept acceleration): without the promise,
// GCC at -O2 keeps such loops scalar. Used only on the parameters of a small inlined loop whose objects
// are distinct by the step's contract.
#ifndef ODESTEP_RESTRICT
#if defined(__GNUC__) || defined(__clang__)
#define ODESTEP_RESTRICT __restrict
#else
#define ODESTEP_RESTRICT
#endif
#endif

// The non-finite path of a step is the rare one: the compiler lays it out of line, so that the ordinary
// path runs straight through.
#ifndef ODESTEP_UNLIKELY
#if defined(__GNUC__) || defined(__clang__)
#define ODESTEP_UNLIKELY(condition) __builtin_expect(static_cast<bool>(condition), 0)
#else
#define ODESTEP_UNLIKELY(condition) (condition)
#endif
#endif

// The event loop's rare path (a crossing, a probe, a NaN) is kept out of line, so that a quiet step's frame
// and registers hold only what a quiet step needs.
#ifndef ODESTEP_EVENTS_NOINLINE
#define ODESTEP_EVENTS_NOINLINE ODESTEP_NOINLINE
#endif

namespace odestep::detail {
/// True where the build optimizes for size (-Os, -Oz): the loops over the components stay loops there,
/// and a few choices between two equivalent forms of a computation follow (the step's finiteness sum).
#if defined(__OPTIMIZE_SIZE__)
inline constexpr bool optimizing_for_size = true;
#else
inline constexpr bool optimizing_for_size = false;
#endif
}  // namespace odestep::detail

#endif
