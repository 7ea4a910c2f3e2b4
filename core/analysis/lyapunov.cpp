#include "core/analysis/lyapunov.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "core/analysis/monodromy.h"

namespace vibro {

LyapunovSpectrum lyapunov_spectrum(const Model& model, const std::vector<PathSegment>& path,
                                   double rtol, double t_from) {
  LyapunovSpectrum out;
  const int n = 2 * model.size();
  std::size_t first = 0;
  while (first < path.size() && path[first].t_end <= t_from) ++first;
  if (first == path.size()) return out;
  Mat Q = Mat::Identity(n, n);
  std::vector<double> sums(n, 0.0);
  for (std::size_t k = first; k < path.size(); ++k) {
    const PathJacobian step = segment_jacobian(model, path, k, rtol);
    if (!step.unsupported.empty()) {
      out.unsupported = step.unsupported;
      return out;
    }
    const Eigen::HouseholderQR<Mat> qr(step.matrix * Q);
    const Mat R = qr.matrixQR().triangularView<Eigen::Upper>();
    Q = qr.householderQ();
    for (int i = 0; i < n; ++i) {
      // The frame keeps its orientation: a negative stretch flips the column with it.
      if (R(i, i) < 0.0) Q.col(i) = -Q.col(i);
      sums[i] += std::log(std::abs(R(i, i)));
    }
  }
  out.span = path.back().t_end - path[first].t;
  if (!(out.span > 0.0)) return out;
  for (double s : sums) out.exponents.push_back(s / out.span);
  std::sort(out.exponents.begin(), out.exponents.end(), std::greater<>());
  return out;
}

}  // namespace vibro
