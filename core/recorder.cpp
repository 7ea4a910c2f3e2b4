#include "core/recorder.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "core/dynamics.h"

namespace vibro {
namespace {
constexpr std::size_t kMaxWarnings = 100;
const double kNone = std::numeric_limits<double>::quiet_NaN();
}  // namespace

Recorder::Recorder(const Model& model, const std::vector<bool>& record, double record_until)
    : model_(model),
      track_of_(model.size(), -1),
      open_(model.size(), false),
      record_until_(record_until),
      negative_since_(model.size(), kNone) {
  for (int i = 0; i < model.size(); ++i) {
    if (i < static_cast<int>(record.size()) && record[i]) {
      track_of_[i] = static_cast<int>(tracks_.size());
      tracks_.push_back({i, {}});
    }
  }
}

void Recorder::sample(double t, const Vec& y) {
  if (t <= record_until_) {
    for (PelletTrack& track : tracks_) {
      const int i = track.pellet;
      if (!open_[i]) {
        track.branches.push_back({static_cast<int>(track.branches.size()) + 1, {}});
        open_[i] = true;
      }
      track.branches.back().samples.push_back({t, y[phi_index(i)], y[dphi_index(i)]});
    }
  }
}

void Recorder::check_normal_force(double t, const Vec& y, const std::vector<Body>& bodies) {
  if (model_.friction != FrictionLaw::paper || model_.alpha0 == 0.0) return;
  for (const Body& b : bodies) {
    const double phi = y[phi_index(b.leader())], dphi = y[dphi_index(b.leader())];
    const bool negative = b.mode == Mode::sliding && normal_per_mass(model_, phi, dphi) < 0.0;
    for (int i : b.members) {
      if (negative && std::isnan(negative_since_[i])) negative_since_[i] = t;
      if (!negative) close_warning(i, t);
    }
  }
}

void Recorder::close_warning(int pellet, double t) {
  if (std::isnan(negative_since_[pellet])) return;
  if (warnings_.size() < kMaxWarnings) {
    std::ostringstream msg;
    msg << "pellet " << pellet + 1 << ": the normal force g cos(phi) + R dphi^2 is negative from t = "
        << negative_since_[pellet] << " s to " << t
        << " s; there the paper's friction law pushes the pellet along (not physical)";
    warnings_.push_back({"negative_normal_force", msg.str(), pellet, negative_since_[pellet], t});
  }
  negative_since_[pellet] = kNone;
}

void Recorder::end_branch(int pellet) { open_[pellet] = false; }

void Recorder::finish(double t, RunResult& result) {
  for (int i = 0; i < model_.size(); ++i) close_warning(i, t);
  result.tracks = std::move(tracks_);
  result.warnings = std::move(warnings_);
}

}  // namespace vibro
