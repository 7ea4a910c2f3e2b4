// One motion interval, between two event instants: the bodies and their modes, the watches
// whose roots end it, and the equations the integrator follows. Built once at the start of the
// interval from the state there; nothing in it changes until the next instant.
#pragma once

#include <optional>
#include <vector>

#include "core/events/contacts.h"
#include "core/events/event_tolerances.h"
#include "core/events/watch.h"
#include "core/model/dynamics.h"
#include "core/model/first_integral.h"
#include "core/model/model.h"
#include "core/model/motion.h"

namespace vibro {

class MotionInterval {
 public:
  // The interval that starts at (t, y) with these bodies; `armed` says which limiters act.
  // With pass_reversals, a frictionless sliding body of one pellet, whose speed's zero changes
  // no equation, is not watched for its reversal: it watches the limiters on both sides of it
  // instead, so its reversals end no interval and are no events (SolverOptions::
  // frictionless_reversals); its s is then the way it went when the interval opened, until
  // align_directions.
  MotionInterval(const Model& model, std::vector<Body> bodies, const std::vector<bool>& armed,
                 const std::vector<Neighbours>& neighbours, double t, const Vec& y,
                 const EventTolerances& tol, bool pass_reversals = false);
  // Becomes the interval that starts at (t, y) with `bodies`, in place of this one, whose
  // storage it reuses: it takes the contents of `bodies` and leaves there the bodies it had
  // (their storage for the caller's next ones).
  void reopen(std::vector<Body>& bodies, const std::vector<bool>& armed,
              const std::vector<Neighbours>& neighbours, double t, const Vec& y,
              const EventTolerances& tol);
  // The dynamics read the bodies in place.
  MotionInterval(const MotionInterval&) = delete;
  MotionInterval& operator=(const MotionInterval&) = delete;

  const std::vector<Body>& bodies() const { return bodies_; }
  const std::vector<Watch>& watches() const { return watches_; }
  const SegmentDynamics& dynamics() const { return dynamics_; }

  // Sets the s of each body that passes its reversals to the way it moves in the state y (kept
  // where it is at rest), before an instant reads the bodies. The equations do not change: such
  // a body has no friction, the one term s enters.
  void align_directions(const Vec& y);

  // Everything rests and nothing can pull it away: the rest of the run is known.
  bool at_rest_for_good() const { return !anything_moves_ && !forced_rest_; }
  // The largest residual of the exact first integral (unforced paper-law bodies of one pellet)
  // at the state y, relative; 0 where none applies.
  double first_integral_residual(const Vec& y) const;

 private:
  // The watches and first integrals of the bodies_ from (t, y), into empty lists.
  void open(const std::vector<bool>& armed, const std::vector<Neighbours>& neighbours, double t,
            const Vec& y, const EventTolerances& tol);
  // A body's own watches: a sliding one's reversal and next limiter (or, passing its reversals,
  // the limiters on both sides: passes_reversals) and its first integral, where one applies; a
  // held one's release if a force can pull it; each cut's separation.
  void add_body_watches(int b, const std::vector<bool>& armed, const Vec& y,
                        const PlaceRadii& radii, double accel_round_off);
  // The watch of the next limiter on `side` of body b (side·(angle − phi) > from), if any.
  void add_limiter_watch(int b, const std::vector<bool>& armed, const Vec& y, int side,
                         double from);
  // Whether body b's reversals are passed (see the constructor).
  bool passes_reversals(const Body& body) const;
  // A body that passes its reversals and starts on the limiter behind it (an impact's rebound,
  // or let go from a rest there) watches that limiter deflated, so its return is found.
  void deflate_limiters_left(double t, const Vec& y, const Vec& dydt, double on_limiter);
  // A body that starts from rest starts on its reversal watch's root: watched in its deflated
  // form, which starts at the acceleration s·φ̈ > 0, a turn back within the first step is found.
  void deflate_reversals_from_rest(double t, const Vec& y, const Vec& dydt);
  // The bilateral law's kink: the normal force's sign, watched from the side it starts on, or,
  // starting on its root (the kink just passed), from the side it moves to.
  void add_normal_watches(double t, const Vec& y, const Vec& dydt);
  // Gaps between neighbours in different bodies; one that starts touching (within `contact`,
  // rad) is watched deflated, a parting speed within v_eps (rad/s) taken as none.
  void add_gap_watches(const std::vector<Neighbours>& neighbours, double t, const Vec& y,
                       const Vec& dydt, double contact, double v_eps);

  const Model& model_;
  std::vector<Body> bodies_;
  std::vector<Watch> watches_;
  std::vector<std::optional<FirstIntegral>> first_integrals_;  // per body
  SegmentDynamics dynamics_;                                   // reads bodies_, declared before it
  bool anything_moves_ = false;
  bool forced_rest_ = false;
  bool pass_reversals_ = false;
  // Scratch of open(): the state's rates at the start, and each pellet's body.
  Vec dydt_;
  std::vector<int> body_of_;
};

}  // namespace vibro
