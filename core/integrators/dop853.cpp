#include "core/integrators/dop853.h"

#include <cmath>

#include "core/integrators/dop853_coefficients.h"

namespace vibro::integrators {

template class ExplicitRk<Dop853Scheme>;

using namespace dop853;

void Dop853Scheme::resize(int n) {
  for (int s = 2; s <= 16; ++s) {
    if (s != 13) k_[s].resize(n);
  }
  yt_.resize(n);
  y12_.resize(n);
  for (Vec& r : r_) r.resize(n);
}

double Dop853Scheme::attempt(const OdeSystem& sys, double t, const Vec& y, const Vec& k1, double h,
                             const Tolerance& tol, Vec& y1, Vec&) {
  const Eigen::Index n = y.size();
  Vec &k2 = k_[2], &k3 = k_[3], &k4 = k_[4], &k5 = k_[5], &k6 = k_[6], &k7 = k_[7], &k8 = k_[8],
      &k9 = k_[9], &k10 = k_[10], &k11 = k_[11], &k12 = k_[12];
  for (Eigen::Index i = 0; i < n; ++i) yt_[i] = y[i] + h * a21 * k1[i];
  sys.rhs(t + c2 * h, yt_, k2);
  for (Eigen::Index i = 0; i < n; ++i) yt_[i] = y[i] + h * (a31 * k1[i] + a32 * k2[i]);
  sys.rhs(t + c3 * h, yt_, k3);
  for (Eigen::Index i = 0; i < n; ++i) yt_[i] = y[i] + h * (a41 * k1[i] + a43 * k3[i]);
  sys.rhs(t + c4 * h, yt_, k4);
  for (Eigen::Index i = 0; i < n; ++i) {
    yt_[i] = y[i] + h * (a51 * k1[i] + a53 * k3[i] + a54 * k4[i]);
  }
  sys.rhs(t + c5 * h, yt_, k5);
  for (Eigen::Index i = 0; i < n; ++i) {
    yt_[i] = y[i] + h * (a61 * k1[i] + a64 * k4[i] + a65 * k5[i]);
  }
  sys.rhs(t + c6 * h, yt_, k6);
  for (Eigen::Index i = 0; i < n; ++i) {
    yt_[i] = y[i] + h * (a71 * k1[i] + a74 * k4[i] + a75 * k5[i] + a76 * k6[i]);
  }
  sys.rhs(t + c7 * h, yt_, k7);
  for (Eigen::Index i = 0; i < n; ++i) {
    yt_[i] = y[i] + h * (a81 * k1[i] + a84 * k4[i] + a85 * k5[i] + a86 * k6[i] + a87 * k7[i]);
  }
  sys.rhs(t + c8 * h, yt_, k8);
  for (Eigen::Index i = 0; i < n; ++i) {
    yt_[i] = y[i] + h * (a91 * k1[i] + a94 * k4[i] + a95 * k5[i] + a96 * k6[i] + a97 * k7[i] +
                         a98 * k8[i]);
  }
  sys.rhs(t + c9 * h, yt_, k9);
  for (Eigen::Index i = 0; i < n; ++i) {
    yt_[i] = y[i] + h * (a101 * k1[i] + a104 * k4[i] + a105 * k5[i] + a106 * k6[i] + a107 * k7[i] +
                         a108 * k8[i] + a109 * k9[i]);
  }
  sys.rhs(t + c10 * h, yt_, k10);
  for (Eigen::Index i = 0; i < n; ++i) {
    yt_[i] = y[i] + h * (a111 * k1[i] + a114 * k4[i] + a115 * k5[i] + a116 * k6[i] + a117 * k7[i] +
                         a118 * k8[i] + a119 * k9[i] + a1110 * k10[i]);
  }
  sys.rhs(t + c11 * h, yt_, k11);
  for (Eigen::Index i = 0; i < n; ++i) {
    y12_[i] = y[i] + h * (a121 * k1[i] + a124 * k4[i] + a125 * k5[i] + a126 * k6[i] + a127 * k7[i] +
                          a128 * k8[i] + a129 * k9[i] + a1210 * k10[i] + a1211 * k11[i]);
  }
  sys.rhs(t + h, y12_, k12);

  // DOP853's error: the 5th-order estimate err5, damped by the 3rd-order one err3 where that is
  // much larger, err = h·err5² / sqrt(n·(err5² + 0.01·err3²)) in the weighted norm.
  double err3 = 0.0;
  double err5 = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double incr = b1 * k1[i] + b6 * k6[i] + b7 * k7[i] + b8 * k8[i] + b9 * k9[i] +
                        b10 * k10[i] + b11 * k11[i] + b12 * k12[i];
    y1[i] = y[i] + h * incr;
    const double sk = tol.scale(y[i], y1[i]);
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
  const Eigen::Index n = y0.size();
  const Vec &k6 = k_[6], &k7 = k_[7], &k8 = k_[8], &k9 = k_[9], &k10 = k_[10], &k11 = k_[11],
            &k12 = k_[12];
  Vec &k14 = k_[14], &k15 = k_[15], &k16 = k_[16];
  for (Eigen::Index i = 0; i < n; ++i) {
    yt_[i] = y0[i] + h * (a141 * k1[i] + a147 * k7[i] + a148 * k8[i] + a149 * k9[i] +
                          a1410 * k10[i] + a1411 * k11[i] + a1412 * k12[i] + a1413 * k13[i]);
  }
  sys.rhs(t0 + c14 * h, yt_, k14);
  for (Eigen::Index i = 0; i < n; ++i) {
    yt_[i] = y0[i] + h * (a151 * k1[i] + a156 * k6[i] + a157 * k7[i] + a158 * k8[i] +
                          a1511 * k11[i] + a1512 * k12[i] + a1513 * k13[i] + a1514 * k14[i]);
  }
  sys.rhs(t0 + c15 * h, yt_, k15);
  for (Eigen::Index i = 0; i < n; ++i) {
    yt_[i] = y0[i] + h * (a161 * k1[i] + a166 * k6[i] + a167 * k7[i] + a168 * k8[i] + a169 * k9[i] +
                          a1613 * k13[i] + a1614 * k14[i] + a1615 * k15[i]);
  }
  sys.rhs(t0 + c16 * h, yt_, k16);

  for (Eigen::Index i = 0; i < n; ++i) {
    const double ydiff = y1[i] - y0[i];
    const double bspl = h * k1[i] - ydiff;
    r_[0][i] = y0[i];
    r_[1][i] = ydiff;
    r_[2][i] = bspl;
    r_[3][i] = ydiff - h * k13[i] - bspl;
    r_[4][i] = h * (d41 * k1[i] + d46 * k6[i] + d47 * k7[i] + d48 * k8[i] + d49 * k9[i] +
                    d410 * k10[i] + d411 * k11[i] + d412 * k12[i] + d413 * k13[i] + d414 * k14[i] +
                    d415 * k15[i] + d416 * k16[i]);
    r_[5][i] = h * (d51 * k1[i] + d56 * k6[i] + d57 * k7[i] + d58 * k8[i] + d59 * k9[i] +
                    d510 * k10[i] + d511 * k11[i] + d512 * k12[i] + d513 * k13[i] + d514 * k14[i] +
                    d515 * k15[i] + d516 * k16[i]);
    r_[6][i] = h * (d61 * k1[i] + d66 * k6[i] + d67 * k7[i] + d68 * k8[i] + d69 * k9[i] +
                    d610 * k10[i] + d611 * k11[i] + d612 * k12[i] + d613 * k13[i] + d614 * k14[i] +
                    d615 * k15[i] + d616 * k16[i]);
    r_[7][i] = h * (d71 * k1[i] + d76 * k6[i] + d77 * k7[i] + d78 * k8[i] + d79 * k9[i] +
                    d710 * k10[i] + d711 * k11[i] + d712 * k12[i] + d713 * k13[i] + d714 * k14[i] +
                    d715 * k15[i] + d716 * k16[i]);
  }
}

void Dop853Scheme::dense(double theta, Vec& out) const {
  const double s = theta;
  const double s1 = 1.0 - theta;
  const Eigen::Index n = r_[0].size();
  for (Eigen::Index i = 0; i < n; ++i) {
    const double conp = r_[4][i] + s * (r_[5][i] + s1 * (r_[6][i] + s * r_[7][i]));
    out[i] = r_[0][i] + s * (r_[1][i] + s1 * (r_[2][i] + s * (r_[3][i] + s1 * conp)));
  }
}

}  // namespace vibro::integrators
