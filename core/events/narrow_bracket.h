// Narrowing a bracket of a sign change to a tolerance by the Anderson–Björck secant: the root
// finder of polynomial steps' events (core/events/polynomial_roots.cpp) and of the normal force's
// windows (core/run/recorder.cpp).
#pragma once

#include <cmath>

namespace vibro {

// A bracket [lo, hi] of a sign change of f, with f's values at its ends.
struct SignBracket {
  double lo = 0.0, hi = 0.0, f_lo = 0.0, f_hi = 0.0;
};

// The factor by which the Anderson–Björck method scales the value kept at one end of a bracket
// when the other end moves twice in a row, from that end's value before (f_old) and after (f_new)
// the move: 1 − f_new/f_old, or the Illinois method's ½ where that is not positive.
inline double anderson_bjorck(double f_new, double f_old) {
  const double m = 1.0 - f_new / f_old;
  return m > 0.0 ? m : 0.5;
}

// Narrows [lo, hi], f(lo) > 0 >= f(hi) (or the reverse when `falling` is false), until it is no
// wider than tolerance(hi): f is taken as monotone there, so each cut keeps the one sign change.
// The cut is the secant of the Anderson–Björck method (the kept end's value scaled down when the
// same end is kept twice), and every fourth cut a bisection unless the bracket has narrowed to an
// eighth of its width since the fourth cut before (or the start): some six cuts instead of
// bisection's fifty, and never fewer halvings than a quarter of bisection's. A secant that falls
// within half the tolerance of an end says that end is within the tolerance of the root: the cut
// goes half the tolerance past it, which brackets the root at once where it is right (a bisection
// there would leave the far end to be halved down, some forty cuts).
template <class F, class Tolerance>
SignBracket narrow_bracket(F&& f, SignBracket b, bool falling, Tolerance&& tolerance) {
  double f_lo = b.f_lo, f_hi = b.f_hi;  // the secant's values, scaled by anderson_bjorck
  int kept = 0;                         // the end kept by the last cut: −1 lo, +1 hi
  double width = b.hi - b.lo;           // the bracket's width at the last fourth cut
  for (int k = 0; k < 200 && b.hi - b.lo > tolerance(b.hi); ++k) {
    const double least = 0.5 * tolerance(b.hi);  // a cut's least distance from an end
    double x = b.lo - f_lo * (b.hi - b.lo) / (f_hi - f_lo);
    if (k % 4 == 3) {
      if (b.hi - b.lo > 0.125 * width) x = 0.5 * (b.lo + b.hi);
      width = b.hi - b.lo;
    }
    if (!(x > b.lo + least))
      x = b.lo + least;
    else if (!(x < b.hi - least))
      x = b.hi - least;
    if (!(x > b.lo && x < b.hi)) x = 0.5 * (b.lo + b.hi);
    if (!(x > b.lo && x < b.hi)) break;
    const double p = f(x);
    if ((p > 0.0) == falling) {
      if (kept == 1) f_hi *= anderson_bjorck(p, f_lo);
      b.lo = x;
      b.f_lo = f_lo = p;
      kept = 1;
    } else {
      if (kept == -1) f_lo *= anderson_bjorck(p, f_hi);
      b.hi = x;
      b.f_hi = f_hi = p;
      kept = -1;
    }
  }
  return b;
}

}  // namespace vibro
