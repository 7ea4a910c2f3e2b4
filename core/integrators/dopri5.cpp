#include "core/integrators/dopri5.h"

#include "core/integrators/rk_sum.h"

namespace vibro::integrators {

template class ExplicitRk<Dopri5Scheme>;

namespace {
// Coefficients of DOPRI5 (Hairer, Nørsett & Wanner, Solving ODEs I, Table II.5.2).
constexpr double c2 = 0.2, c3 = 0.3, c4 = 0.8, c5 = 8.0 / 9.0;
constexpr double a21 = 0.2;
constexpr double a31 = 3.0 / 40.0, a32 = 9.0 / 40.0;
constexpr double a41 = 44.0 / 45.0, a42 = -56.0 / 15.0, a43 = 32.0 / 9.0;
constexpr double a51 = 19372.0 / 6561.0, a52 = -25360.0 / 2187.0, a53 = 64448.0 / 6561.0,
                 a54 = -212.0 / 729.0;
constexpr double a61 = 9017.0 / 3168.0, a62 = -355.0 / 33.0, a63 = 46732.0 / 5247.0,
                 a64 = 49.0 / 176.0, a65 = -5103.0 / 18656.0;
constexpr double a71 = 35.0 / 384.0, a73 = 500.0 / 1113.0, a74 = 125.0 / 192.0,
                 a75 = -2187.0 / 6784.0, a76 = 11.0 / 84.0;
constexpr double e1 = 71.0 / 57600.0, e3 = -71.0 / 16695.0, e4 = 71.0 / 1920.0,
                 e5 = -17253.0 / 339200.0, e6 = 22.0 / 525.0, e7 = -1.0 / 40.0;
// Dense output of Shampine (DOPRI5's CONTD5).
constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                 d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                 d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;
}  // namespace

void Dopri5Scheme::resize(int n) {
  for (Vec* v : {&k2_, &k3_, &k4_, &k5_, &k6_, &yt_, &y6_, &err_}) v->resize(n);
  dense_.resize(n);
}

double Dopri5Scheme::attempt(const OdeSystem& sys, double t, const Vec& y, const Vec& k1, double h,
                             const Tolerance& tol, Vec& y1, Vec& k7) {
  rk_sum(yt_, y, h, Term{a21, k1});
  sys.rhs(t + c2 * h, yt_, k2_);
  rk_sum(yt_, y, h, Term{a31, k1}, Term{a32, k2_});
  sys.rhs(t + c3 * h, yt_, k3_);
  rk_sum(yt_, y, h, Term{a41, k1}, Term{a42, k2_}, Term{a43, k3_});
  sys.rhs(t + c4 * h, yt_, k4_);
  rk_sum(yt_, y, h, Term{a51, k1}, Term{a52, k2_}, Term{a53, k3_}, Term{a54, k4_});
  sys.rhs(t + c5 * h, yt_, k5_);
  rk_sum(y6_, y, h, Term{a61, k1}, Term{a62, k2_}, Term{a63, k3_}, Term{a64, k4_}, Term{a65, k5_});
  sys.rhs(t + h, y6_, k6_);
  rk_sum(y1, y, h, Term{a71, k1}, Term{a73, k3_}, Term{a74, k4_}, Term{a75, k5_}, Term{a76, k6_});
  sys.rhs(t + h, y1, k7);
  rk_sum(err_, h, Term{e1, k1}, Term{e3, k3_}, Term{e4, k4_}, Term{e5, k5_}, Term{e6, k6_},
         Term{e7, k7});
  return rms_norm(err_, y, y1, tol);
}

void Dopri5Scheme::prepare_dense(const OdeSystem&, double, const Vec& y0, const Vec& k1, double h,
                                 const Vec& y1, const Vec& k7) {
  dense_.set_ends(y0, y1, k1, k7, h);
  rk_sum(dense_.correction(0), h, Term{d1, k1}, Term{d3, k3_}, Term{d4, k4_}, Term{d5, k5_},
         Term{d6, k6_}, Term{d7, k7});
}

}  // namespace vibro::integrators
