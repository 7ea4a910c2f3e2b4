#include "core/integrators/dop853.h"

#include <cmath>

#include "core/integrators/dop853_coefficients.h"
#include "core/integrators/rk_sum.h"

namespace vibro::integrators {

template class ExplicitRk<Dop853Scheme>;

using namespace dop853;

void Dop853Scheme::resize(int n) {
  for (int s = 2; s <= 16; ++s) {
    if (s != 13) k_[s].resize(n);
  }
  yt_.resize(n);
  y12_.resize(n);
  dense_.resize(n);
}

double Dop853Scheme::attempt(const OdeSystem& sys, double t, const Vec& y, const Vec& k1, double h,
                             const Tolerance& tol, Vec& y1, Vec&) {
  Vec &k2 = k_[2], &k3 = k_[3], &k4 = k_[4], &k5 = k_[5], &k6 = k_[6], &k7 = k_[7], &k8 = k_[8],
      &k9 = k_[9], &k10 = k_[10], &k11 = k_[11], &k12 = k_[12];
  rk_sum(yt_, y, h, Term{a21, k1});
  sys.rhs(t + c2 * h, yt_, k2);
  rk_sum(yt_, y, h, Term{a31, k1}, Term{a32, k2});
  sys.rhs(t + c3 * h, yt_, k3);
  rk_sum(yt_, y, h, Term{a41, k1}, Term{a43, k3});
  sys.rhs(t + c4 * h, yt_, k4);
  rk_sum(yt_, y, h, Term{a51, k1}, Term{a53, k3}, Term{a54, k4});
  sys.rhs(t + c5 * h, yt_, k5);
  rk_sum(yt_, y, h, Term{a61, k1}, Term{a64, k4}, Term{a65, k5});
  sys.rhs(t + c6 * h, yt_, k6);
  rk_sum(yt_, y, h, Term{a71, k1}, Term{a74, k4}, Term{a75, k5}, Term{a76, k6});
  sys.rhs(t + c7 * h, yt_, k7);
  rk_sum(yt_, y, h, Term{a81, k1}, Term{a84, k4}, Term{a85, k5}, Term{a86, k6}, Term{a87, k7});
  sys.rhs(t + c8 * h, yt_, k8);
  rk_sum(yt_, y, h, Term{a91, k1}, Term{a94, k4}, Term{a95, k5}, Term{a96, k6}, Term{a97, k7},
         Term{a98, k8});
  sys.rhs(t + c9 * h, yt_, k9);
  rk_sum(yt_, y, h, Term{a101, k1}, Term{a104, k4}, Term{a105, k5}, Term{a106, k6}, Term{a107, k7},
         Term{a108, k8}, Term{a109, k9});
  sys.rhs(t + c10 * h, yt_, k10);
  rk_sum(yt_, y, h, Term{a111, k1}, Term{a114, k4}, Term{a115, k5}, Term{a116, k6}, Term{a117, k7},
         Term{a118, k8}, Term{a119, k9}, Term{a1110, k10});
  sys.rhs(t + c11 * h, yt_, k11);
  rk_sum(y12_, y, h, Term{a121, k1}, Term{a124, k4}, Term{a125, k5}, Term{a126, k6}, Term{a127, k7},
         Term{a128, k8}, Term{a129, k9}, Term{a1210, k10}, Term{a1211, k11});
  sys.rhs(t + h, y12_, k12);

  // DOP853's error: the 5th-order estimate err5, damped by the 3rd-order one err3 where that is
  // much larger, err = h·err5² / sqrt(n·(err5² + 0.01·err3²)) in the weighted norm.
  const Eigen::Index n = y.size();
  double err3 = 0.0;
  double err5 = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double incr = b1 * k1[i] + b6 * k6[i] + b7 * k7[i] + b8 * k8[i] + b9 * k9[i] +
                        b10 * k10[i] + b11 * k11[i] + b12 * k12[i];
    y1[i] = y[i] + h * incr;
    const double sk = tol.scale(i, y[i], y1[i]);
    const double e3 = (incr - bhh1 * k1[i] - bhh2 * k9[i] - bhh3 * k12[i]) / sk;
    const double e5 = (er1 * k1[i] + er6 * k6[i] + er7 * k7[i] + er8 * k8[i] + er9 * k9[i] +
                       er10 * k10[i] + er11 * k11[i] + er12 * k12[i]) /
                      sk;
    err3 += e3 * e3;
    err5 += e5 * e5;
  }
  double deno = err5 + 0.01 * err3;
  if (deno <= 0.0) deno = 1.0;
  return std::abs(h) * err5 * std::sqrt(1.0 / (static_cast<double>(n) * deno));
}

void Dop853Scheme::prepare_dense(const OdeSystem& sys, double t0, const Vec& y0, const Vec& k1,
                                 double h, const Vec& y1, const Vec& k13) {
  const Vec &k6 = k_[6], &k7 = k_[7], &k8 = k_[8], &k9 = k_[9], &k10 = k_[10], &k11 = k_[11],
            &k12 = k_[12];
  Vec &k14 = k_[14], &k15 = k_[15], &k16 = k_[16];
  // The three extra stages of the 7th-order interpolant.
  rk_sum(yt_, y0, h, Term{a141, k1}, Term{a147, k7}, Term{a148, k8}, Term{a149, k9},
         Term{a1410, k10}, Term{a1411, k11}, Term{a1412, k12}, Term{a1413, k13});
  sys.rhs(t0 + c14 * h, yt_, k14);
  rk_sum(yt_, y0, h, Term{a151, k1}, Term{a156, k6}, Term{a157, k7}, Term{a158, k8},
         Term{a1511, k11}, Term{a1512, k12}, Term{a1513, k13}, Term{a1514, k14});
  sys.rhs(t0 + c15 * h, yt_, k15);
  rk_sum(yt_, y0, h, Term{a161, k1}, Term{a166, k6}, Term{a167, k7}, Term{a168, k8}, Term{a169, k9},
         Term{a1613, k13}, Term{a1614, k14}, Term{a1615, k15});
  sys.rhs(t0 + c16 * h, yt_, k16);

  dense_.set_ends(y0, y1, k1, k13, h);
  rk_sum(dense_.correction(0), h, Term{d41, k1}, Term{d46, k6}, Term{d47, k7}, Term{d48, k8},
         Term{d49, k9}, Term{d410, k10}, Term{d411, k11}, Term{d412, k12}, Term{d413, k13},
         Term{d414, k14}, Term{d415, k15}, Term{d416, k16});
  rk_sum(dense_.correction(1), h, Term{d51, k1}, Term{d56, k6}, Term{d57, k7}, Term{d58, k8},
         Term{d59, k9}, Term{d510, k10}, Term{d511, k11}, Term{d512, k12}, Term{d513, k13},
         Term{d514, k14}, Term{d515, k15}, Term{d516, k16});
  rk_sum(dense_.correction(2), h, Term{d61, k1}, Term{d66, k6}, Term{d67, k7}, Term{d68, k8},
         Term{d69, k9}, Term{d610, k10}, Term{d611, k11}, Term{d612, k12}, Term{d613, k13},
         Term{d614, k14}, Term{d615, k15}, Term{d616, k16});
  rk_sum(dense_.correction(3), h, Term{d71, k1}, Term{d76, k6}, Term{d77, k7}, Term{d78, k8},
         Term{d79, k9}, Term{d710, k10}, Term{d711, k11}, Term{d712, k12}, Term{d713, k13},
         Term{d714, k14}, Term{d715, k15}, Term{d716, k16});
}

}  // namespace vibro::integrators
