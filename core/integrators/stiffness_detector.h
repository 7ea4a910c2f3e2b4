// Hairer's stiffness detection of DOPRI5 and DOP853.
#pragma once

namespace vibro::integrators {

// Fed with h·ρ after each accepted step (ρ: a Rayleigh-quotient estimate of the dominant
// eigenvalue of ∂f/∂y from the last two stages). The problem is declared stiff once h·ρ exceeded
// the method's stability bound in 15 accepted steps, with fewer than 6 non-stiff steps in a row
// in between. Unlike Hairer's codes (which look only every NSTIFF=1000 steps until the first
// hit) it looks at every step, so that "auto" can switch promptly. With a `fraction` below 1 it
// counts steps whose h·ρ came within that fraction of the boundary: a step size held there by
// stability rather than accuracy, which Hairer's test can miss when the controller keeps h·ρ
// just under the boundary.
class StiffnessDetector {
 public:
  static constexpr int kStiffSteps = 15;
  static constexpr int kForgivingSteps = 6;

  explicit StiffnessDetector(double fraction = 1.0) : fraction_(fraction) {}

  void record(double h_rho, double bound) {
    if (h_rho > fraction_ * bound) {
      non_stiff_ = 0;
      ++stiff_;
    } else if (++non_stiff_ == kForgivingSteps) {
      stiff_ = 0;
    }
  }

  bool stiff() const { return stiff_ >= kStiffSteps; }

  void reset() {
    stiff_ = 0;
    non_stiff_ = 0;
  }

 private:
  double fraction_;
  int stiff_ = 0;
  int non_stiff_ = 0;
};

}  // namespace vibro::integrators
