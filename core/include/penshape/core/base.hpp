#pragma once
// What every layer of core shares, from the geometry kernel up to the engines and the recognizer:
// the exact number type, the error a refused input raises, and the cancel hook of long
// computations. Nothing here depends on an engine; deconstruct.hpp and polygon_set.hpp build on it.
#include <gmpxx.h>

#include <functional>
#include <stdexcept>

namespace penshape {

// GMP needs canonical rationals (lowest terms, positive denominator): mpq_class(p, q) is not
// canonical unless p/q already is; call canonicalize() after building one from a fraction.
using Rational = mpq_class;

// Called now and then inside long computations; returning true aborts with Cancelled.
using CancelHook = std::function<bool()>;

// Thrown when a CancelHook asked to stop.
struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("cancelled") {}
};

// Thrown for input the engines refuse; the message names the problem (which polygon, ring and
// vertex, which parameter, which bound).
struct InvalidInput : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

} // namespace penshape
