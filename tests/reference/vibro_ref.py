#!/usr/bin/python3
"""Independent reference simulator for the vibro-impact model (shared/MODEL.md).

Written from the physics contract (shared/MODEL.md), the scene format (shared/API.md) and the
engine's documented choices (docs/MODEL.md) only, never from the engine's code, so that the two can
be compared (differential testing).  Accuracy and clarity matter here, not speed.

Usage:  /usr/bin/python3 vibro_ref.py SCENE.json|- [--rtol 1e-12] [--atol 1e-14]
Prints  {"events": [...], "final": [...], "t_reached": t, "unsupported": null | "why"}.
Python: simulate(scene_dict, rtol=1e-12, atol=1e-14, samples=()) returns the same dict (plus
the states at the sample times).  README.md lists the choices made where the texts leave room.

How it works, in short:
- Pellets that touch and move together form *bodies* (a chain of pellets bonded across the gaps of
  the circular order).  Each body is stuck, resting against a limiter, or sliding with a fixed
  direction s; sliding bodies are integrated together with DOP853 (scipy).
- Every event is the root of a continuous *watch* function that is positive while nothing happens.
  After every accepted step the dense output is sampled (SAMPLES sub-intervals), each watch is
  checked for a sign change and for a dip (a local minimum of the samples is minimised: a root that
  enters and leaves between two samples is found too), and the first root is refined by brentq.
- Roots within 1e-12*(1+t) of the earliest one form one instant, resolved as MODEL.md says: limiter
  contacts first, then touching pairs, sweep after sweep; a cascade that has not settled after 16
  sweeps becomes one plastic impact of the group (docs/MODEL.md).
- What the contract leaves open is settled as docs/MODEL.md says; what neither settles makes the run
  stop with "unsupported" instead of a guess.
"""

import json
import math
import sys

import numpy as np
from scipy.integrate import DOP853
from scipy.optimize import brentq, minimize_scalar

TWO_PI = 2.0 * math.pi
SAME_INSTANT = 1e-12      # roots within 1e-12*(1+t) s are one instant (MODEL.md, docs/MODEL.md)
TOUCH = 1e-10             # neighbours closer than 1e-10*(1+|phi|) rad touch (docs/MODEL.md)
FLIGHT = 1e2 * 2.220446049250313e-16  # pressed pellets parting less (x (1+|phi|) rad) stay joined
SPEED_AGREE = 1e-9        # touching pellets with speeds this close (x speed scale) may bond
CHATTER_TIME = 1e-4       # a series shorter than 1e-4*sqrt(R/g) is summed (docs/MODEL.md)
MAX_SWEEPS = 16           # an instant not settled after 16 sweeps is a cascade (docs/MODEL.md)
ON_LIMITER = 4e-16        # a pellet is on a limiter when snapped onto it (to round-off, rad/rad)
TURNS_ON_LIMITER = 1e-14  # a reversal this close (x (1+|theta|) rad) to a limiter is on it
MAX_EVENTS = 20000
STATE_NAMES = {"slide": "sliding", "stuck": "stuck", "rest": "resting_at_limiter"}
MAX_SAME_INSTANT = 50     # instants in a row at one time without leaving it: the run is stuck
SAMPLES = 9               # sub-intervals of every step at which the watches are evaluated
FORCING_SAMPLES = 64      # at least this many watch samples per forcing period


class Unsupported(Exception):
    """A situation the reference cannot compute faithfully: the run stops there."""


class SceneError(ValueError):
    """The scene is malformed or outside the model (MODEL.md's parameter ranges)."""


# ----------------------------------------------------------------------------------------------
# Scene

class Limiter:
    def __init__(self, d, n_pellets):
        self.theta = float(d["angle"])
        self.k = float(d["k"])
        self.mobile = bool(d.get("mobile", False))
        self.rearm_by = d.get("rearm_by")
        acts = d.get("pellets")
        self.acts = set(range(n_pellets)) if acts is None else {int(p) for p in acts}
        if not 0.0 <= self.k <= 1.0:
            raise SceneError("limiter k must be in [0, 1]")
        if not self.acts <= set(range(n_pellets)):
            raise SceneError("limiter pellets must be pellet indices")


class Model:
    def __init__(self, scene):
        try:
            self.read(scene)
        except (KeyError, TypeError, ValueError) as e:
            raise SceneError("%s: %s" % (type(e).__name__, e)) from e

    def read(self, scene):
        m = scene["model"]
        self.g = float(m.get("g", 9.81))
        self.R = float(m["R"])
        alpha0 = float(m.get("alpha0", 0.0))
        if not (self.R > 0 and 0.0 <= alpha0 < math.pi / 2):
            raise SceneError("need R > 0 and 0 <= alpha0 < pi/2")
        self.mu = math.tan(alpha0)
        self.mu_s = float(m.get("mu_s", self.mu))
        if self.mu_s < self.mu:
            raise SceneError("mu_s < mu is refused by MODEL.md")
        self.law = m.get("friction", "paper")
        if self.law not in ("paper", "bilateral"):
            raise SceneError("friction must be 'paper' or 'bilateral'")
        ps = m["pellets"]
        self.n = len(ps)
        self.m = [float(p["m"]) for p in ps]
        self.phi0 = [float(p["phi0"]) for p in ps]
        self.dphi0 = [float(p["dphi0"]) for p in ps]
        self.F0 = [float(p.get("F0", 0.0)) for p in ps]
        self.Om = [float(p.get("Omega", 0.0)) for p in ps]
        self.psi = [float(p.get("psi", 0.0)) for p in ps]
        self.lims = [Limiter(d, self.n) for d in m.get("limiters", [])]
        self.k_c = float(m.get("k_c", 1.0))
        self.t_end = float(scene["t_end"])
        if self.n < 1 or min(self.m) <= 0 or not 0.0 <= self.k_c <= 1.0 or not self.t_end >= 0:
            raise SceneError("need pellets with m > 0, 0 <= k_c <= 1 and t_end >= 0")
        for L in self.lims:
            if L.mobile and L.rearm_by not in range(len(self.lims)):
                raise SceneError("a mobile limiter needs rearm_by, a limiter index")
        self.w = self.g / self.R              # g/R, s^-2
        self.chatter_time = CHATTER_TIME * math.sqrt(self.R / self.g)
        self.forced = [f != 0.0 for f in self.F0]
        # Time-only watches (release, separation) are sampled at least FORCING_SAMPLES times per
        # period of the fastest forcing; the dynamics' own time scale bounds the step as well.
        periods = [TWO_PI / abs(o) for f, o in zip(self.F0, self.Om) if f != 0.0 and o != 0.0]
        self.h_time = min(periods) * SAMPLES / FORCING_SAMPLES if periods else math.inf
        self.h_max = min(self.h_time, 0.05 * math.sqrt(self.R / self.g))
        self.h_tie = 1e-8 * min([math.sqrt(self.R / self.g)] + periods)

    def force(self, pellets, t):
        """Sum of the tangential forces F_i(t) on the pellets (t scalar or array), N."""
        f = 0.0 * t
        for p in pellets:
            if self.F0[p] != 0.0:
                f = f + self.F0[p] * np.cos(self.Om[p] * t + self.psi[p])
        return f

    def a_free(self, pellets, t, phi):
        """Free tangential acceleration of a group moving as one: forces, gravity, no friction."""
        mass = sum(self.m[p] for p in pellets)
        return self.force(pellets, t) / (mass * self.R) - self.w * np.sin(phi)

    def capacity(self, phi):
        """Static friction's hold per unit mass and radius: mu_s (g/R) |cos phi|."""
        return self.mu_s * self.w * np.abs(np.cos(phi))

    def accel(self, pellets, t, phi, dphi, s):
        """Sliding equation of MODEL.md for a group with direction s (fixed on the interval)."""
        a = self.a_free(pellets, t, phi)
        if self.law == "paper":
            return a - s * self.mu * dphi * dphi - s * self.mu * self.w * np.cos(phi)
        return a - s * self.mu * np.abs(dphi * dphi + self.w * np.cos(phi))

    def kinetic_friction_at_rest(self, phi):
        """Sliding friction at vanishing speed (per unit mass and radius), signed as the law
        has it."""
        c = self.mu * self.w * math.cos(phi)
        return c if self.law == "paper" else abs(c)


def unwrap_ahead(theta, x, s):
    """The limiter angle theta + 2 pi k nearest to x strictly ahead of it in direction s."""
    k = math.floor((x - theta) / TWO_PI)
    if s > 0:
        while theta + TWO_PI * k <= x:
            k += 1
        while theta + TWO_PI * (k - 1) > x:
            k -= 1
    else:
        k += 1
        while theta + TWO_PI * k >= x:
            k -= 1
        while theta + TWO_PI * (k + 1) < x:
            k += 1
    return theta + TWO_PI * k


def unwrap_near(theta, x):
    """The limiter angle theta + 2 pi k nearest to x."""
    return theta + TWO_PI * round((x - theta) / TWO_PI)


# ----------------------------------------------------------------------------------------------
# Watches: functions positive while nothing happens

class Watch:
    """A watch g(t, Y) evaluated on arrays of times (Y: states as columns, None if time-only).

    A watch that starts on its own root (two pellets that just touched, a body just released from
    rest) is watched as (g(t) - g(t0))/(t - t0), which starts at g'(t0) and so catches a quick
    return inside one step (docs/MODEL.md does the same)."""

    def __init__(self, kind, fn, t0, y0, **data):
        self.kind = kind
        self.fn = fn
        self.t0 = t0
        self.data = data
        self.g0 = float(fn(np.array([t0]), None if y0 is None else y0[:, None])[0])
        self.divided = self.g0 <= 0.0

    def values(self, ts, Y):
        v = np.asarray(self.fn(ts, Y), dtype=float) * np.ones_like(ts)
        if not self.divided:
            return v
        dt = ts - self.t0
        out = np.full_like(v, np.inf)        # at t0 itself: "still positive"
        nz = dt > 0
        out[nz] = (v[nz] - self.g0) / dt[nz]
        return out


def first_root(ts, vs, scalar):
    """Bracket of the first root of a watch from its samples, or None.

    A sign change gives the bracket directly; a local minimum of positive samples is minimised over
    its two neighbouring intervals, so that a dip below zero between samples is not missed."""
    for k in range(1, len(ts)):
        if vs[k - 1] > 0.0 and vs[k] <= 0.0:
            return ts[k - 1], ts[k]
        if k + 1 < len(ts) and vs[k] > 0.0 and vs[k] <= vs[k - 1] and vs[k] <= vs[k + 1] \
                and vs[k + 1] > 0.0:
            a, b = ts[k - 1], ts[k + 1]
            res = minimize_scalar(scalar, bounds=(a, b), method="bounded",
                                  options={"xatol": 1e-10 * (b - a)})
            if res.fun <= 0.0:
                return a, res.x
    return None


def refine_root(scalar, a, b, t0):
    """Root of scalar in (a, b] with scalar(a) > 0 >= scalar(b), to round-off in t."""
    fb = scalar(b)
    if fb == 0.0:
        return b
    if not scalar(a) > 0.0 or math.isinf(scalar(a)):
        # a is the watch's own start (divided form): step in until the watch is positive
        lo = None
        for j in range(1, 60):
            c = a + (b - a) * 0.5 ** j
            if c <= t0:
                break
            if 0.0 < scalar(c) < math.inf:
                lo = c
                break
        if lo is None:
            return a                          # it fires at once
        a = lo
    return brentq(scalar, a, b, xtol=1e-300, rtol=4 * np.finfo(float).eps, maxiter=200)


# ----------------------------------------------------------------------------------------------
# The simulator

class Sim:
    def __init__(self, scene, rtol, atol, samples=()):
        self.M = Model(scene)
        self.rtol, self.atol = rtol, atol
        self.sample_times = sorted(samples, reverse=True)    # popped from the end
        self.samples = []
        M = self.M
        self.t = 0.0
        self.phi = list(M.phi0)
        self.dphi = list(M.dphi0)
        self.events = []
        self.armed = [True] * len(M.lims)
        # per pellet, shared by its body: "slide" (direction sgn), "stuck", or "rest" (against
        # the limiter of a contact of the body)
        self.mode = ["slide"] * M.n
        self.sgn = [0] * M.n
        self.contact = [None] * M.n   # (limiter, side, unwrapped angle); side -1: below theta
        self.left = [None] * M.n      # the contact each pellet last moved away from
        self.pending = None           # summed chatter not yet reached: (t*, body, limiter, u)
        # Circular order never changes (pellets do not pass each other); gap k runs from
        # order[k] to order[k+1] and equals phi[next] - phi[this] + 2 pi wind[k] >= 0.
        wrapped = [p % TWO_PI for p in self.phi]
        self.order = sorted(range(M.n), key=lambda i: (wrapped[i], i))
        # The gaps between neighbours lie in [0, 2 pi), the one closing the circle in (0, 2 pi].
        self.wind = []
        if M.n >= 2:
            for k in range(M.n):
                i, j = self.order[k], self.order[(k + 1) % M.n]
                d = self.phi[j] - self.phi[i]
                self.wind.append(math.ceil(-d / TWO_PI) if k < M.n - 1
                                 else math.floor(-d / TWO_PI) + 1)
            assert sum(self.wind) == 1
        self.bond = [False] * len(self.wind)

    # ---- bodies -------------------------------------------------------------------------------

    def gap(self, k):
        i, j = self.order[k], self.order[(k + 1) % self.M.n]
        return self.phi[j] - self.phi[i] + TWO_PI * self.wind[k]

    def bodies(self):
        """Chains of bonded pellets, each listed behind -> ahead (increasing phi)."""
        n = self.M.n
        if n == 1 or not any(self.bond):
            return [(p,) for p in self.order]
        start = [k for k in range(n) if not self.bond[(k - 1) % n]]
        out = []
        for k in start:
            chain = [self.order[k]]
            while self.bond[k % n]:
                k += 1
                chain.append(self.order[k % n])
            out.append(tuple(chain))
        return out

    def body_of(self, p):
        for b in self.bodies():
            if p in b:
                return b
        raise AssertionError

    def set_body(self, body, phi_ref, dphi):
        """Move a body: its first pellet to phi_ref, the others by their 2 pi offsets."""
        ref = body[0]
        shift = phi_ref - self.phi[ref]
        for p in body:
            self.phi[p] = self.phi[p] + shift if p != ref else phi_ref
            self.dphi[p] = dphi

    # ---- events ---------------------------------------------------------------------------------

    def emit(self, kind, pellets, limiter, before, after, **extra):
        ev = {"t": self.t, "kind": kind, "pellets": list(pellets),
              "limiter": -1 if limiter is None else limiter,
              "phi": self.phi[pellets[0]], "dphi_before": list(before), "dphi_after": list(after)}
        ev.update(extra)
        self.events.append(ev)
        if len(self.events) > MAX_EVENTS:
            raise Unsupported("more than %d events" % MAX_EVENTS)

    # ---- modes ---------------------------------------------------------------------------------

    def on_limiter(self, p):
        """The contact of pellet p if it is still on that limiter (it was snapped onto it at an
        impact and has not moved since); a pellet a hair away from it is in flight."""
        c = self.contact[p]
        if c is not None and abs(self.phi[p] - c[2]) <= ON_LIMITER * (1 + abs(c[2])):
            return c
        return None

    def limiter_contact(self, body):
        """(limiter, side) of an armed limiter that a pellet of the body touches, or None."""
        for p in body:
            c = self.on_limiter(p)
            if c is not None and self.armed[c[0]] and p in self.M.lims[c[0]].acts:
                return c[0], c[1]
        return None

    def set_mode(self, body, mode, s=0):
        for p in body:
            self.mode[p], self.sgn[p] = mode, s

    def settle(self, body, cause):
        """Mode of a body after an instant, and the event that says so.

        cause: "release" (its own release watch fired: it leaves), "reversal" (its speed reached
        zero: the stick test, listed as reversal or stick), "start" (it was at rest and may have
        to move now: listed as release if it does), None (nothing to list)."""
        M = self.M
        v = self.dphi[body[0]]
        if v != 0.0:
            self.set_mode(body, "slide", 1 if v > 0 else -1)
            return
        phi = self.phi[body[0]]
        # A release or a part coming off is found on the root of its watch, where the test
        # below is a tie (exactly so without static friction): decide on the forces a moment
        # later, when the watch has clearly changed sign.
        later = M.h_tie if cause in ("release", "start") else 0.0
        a = float(M.a_free(body, self.t + later, phi))
        c = float(M.capacity(phi))
        lim = self.limiter_contact(body)
        if lim is not None:
            side = lim[1]
            if cause == "release" or side * a > c:
                self.set_mode(body, "slide", side)      # pulled away from the limiter
            else:
                self.set_mode(body, "rest")
        elif cause == "release" or abs(a) > c:
            self.set_mode(body, "slide", 1 if a > 0 else -1)
        else:
            self.set_mode(body, "stuck")
        zeros = [0.0] * len(body)
        sliding = self.mode[body[0]] == "slide"
        # The limiter field names the limiter the body comes to rest against or leaves.
        at = lim[0] if lim is not None else None
        if cause == "reversal":
            self.emit("reversal" if sliding else "stick", body, None if sliding else at,
                      zeros, zeros)
        elif cause in ("release", "start") and sliding:
            self.emit("release", body, at, zeros, zeros)

    # ---- watches of the current interval ---------------------------------------------------------

    def build_watches(self, bodies, slide, y0):
        M = self.M
        t0 = self.t
        col = {b: i for i, b in enumerate(slide)}
        watches = []

        def pos_fn(p, body):
            off = self.phi[p] - self.phi[body[0]]
            if body in col:
                i = 2 * col[body]
                return lambda ts, Y: Y[i] + off
            const = self.phi[p]
            return lambda ts, Y: const + 0.0 * ts

        for b in bodies:
            if b in col:
                i, s = 2 * col[b], self.sgn[b[0]]
                watches.append(Watch("reversal", lambda ts, Y, i=i, s=s: s * Y[i + 1],
                                     t0, y0, body=b))
                # Limiters: for each, the frontmost pellet of the body it acts on meets it.
                lead = b[::-1] if s > 0 else b          # front first, in the direction of motion
                for li, L in enumerate(M.lims):
                    if not self.armed[li]:
                        continue
                    hit = [p for p in lead if p in L.acts]
                    if not hit:
                        continue
                    p = hit[0]
                    th = unwrap_ahead(L.theta, self.phi[p], s)
                    f = pos_fn(p, b)
                    watches.append(Watch("limiter",
                                         lambda ts, Y, f=f, th=th, s=s: s * (th - f(ts, Y)),
                                         t0, y0, body=b, pellet=p, limiter=li, theta=th, side=-s))
            elif self.pending is None or self.pending[1] != b:
                phi = self.phi[b[0]]
                c = float(M.capacity(phi))
                lim = self.limiter_contact(b) if self.mode[b[0]] == "rest" else None
                if not any(M.forced[p] for p in b):
                    continue            # without forcing nothing changes a body at rest
                side = lim[1] if lim else None
                fn = (lambda ts, Y, b=b, phi=phi, c=c, side=side:
                      c - (side * M.a_free(b, ts, phi) if side else np.abs(M.a_free(b, ts, phi))))
                watches.append(Watch("release", fn, t0, None, body=b))
            if len(b) > 1 and any(M.forced[p] for p in b):
                watches += self.split_watches(b, t0)
        # gaps between neighbouring bodies, when at least one of them moves
        n = M.n
        if n >= 2:
            body_at = {p: b for b in bodies for p in b}
            for k in range(n):
                if self.bond[k]:
                    continue
                i, j = self.order[k], self.order[(k + 1) % n]
                bi, bj = body_at[i], body_at[j]
                if bi == bj or (bi not in col and bj not in col) or self.limiter_between(k):
                    continue
                fi, fj, wk = pos_fn(i, bi), pos_fn(j, bj), TWO_PI * self.wind[k]
                # Pellets that touch and part (after an impact, or a body that splits with equal
                # speeds) start at gap 0, where round-off alone would read as crossings: the
                # watch is lifted by a few ulps of the angles it is computed from.
                floor = 8 * np.finfo(float).eps * (1 + abs(self.phi[i]) + abs(self.phi[j])
                                                   + abs(wk))
                watches.append(Watch("gap", lambda ts, Y, fi=fi, fj=fj, wk=wk, floor=floor:
                                     fj(ts, Y) - fi(ts, Y) + wk + floor, t0, y0, gap=k))
        return watches

    def split_watches(self, b, t0):
        """Watches that a forced body comes apart (positive while it holds together).

        Moving, only the forces differ between its parts (gravity and friction per unit mass
        are the same for pellets moving together): a cut opens when its compression, the
        difference of the parts' forces, turns negative.  At rest, static friction holds each
        part on its own, so the body comes apart only when an end part is pulled off the rest
        harder than its own friction holds it (not into a limiter the body rests against)."""
        M = self.M
        mass = sum(M.m[p] for p in b)
        out = []
        if self.mode[b[0]] == "slide":
            for j in range(len(b) - 1):
                behind = b[:j + 1]
                mb = sum(M.m[p] for p in behind)
                fn = (lambda ts, Y, behind=behind, mb=mb:
                      (M.force(behind, ts) - mb / mass * M.force(b, ts)) / M.R)
                out.append(Watch("split", fn, t0, None, body=b))
            return out
        phi = self.phi[b[0]]
        c = float(M.capacity(phi))
        lim = self.limiter_contact(b) if self.mode[b[0]] == "rest" else None
        side = lim[1] if lim is not None else 0
        for j in range(len(b) - 1):
            ahead, behind = b[j + 1:], b[:j + 1]
            if side >= 0:       # the part ahead may leave forward
                out.append(Watch("split", lambda ts, Y, ps=ahead: c - M.a_free(ps, ts, phi),
                                 t0, None, body=b))
            if side <= 0:       # the part behind may leave backward
                out.append(Watch("split", lambda ts, Y, ps=behind: c + M.a_free(ps, ts, phi),
                                 t0, None, body=b))
        return out

    # ---- one interval: integrate until the first event ----------------------------------------

    def scan(self, t_stop):
        """Advance to the first event before t_stop; returns the fired watches ([] at t_stop)."""
        bodies = self.bodies()
        slide = [b for b in bodies if self.mode[b[0]] == "slide"]
        for b in slide:
            for p in b:
                if self.contact[p] is not None:
                    self.left[p] = self.contact[p]
                self.contact[p] = None   # moving away: only a new impact makes a new contact
        y0 = np.array([v for b in slide for v in (self.phi[b[0]], self.dphi[b[0]])], dtype=float)
        watches = self.build_watches(bodies, slide, y0 if slide else None)
        if not slide and not watches:
            self.record_samples(t_stop, [], None)
            self.t = t_stop
            return []
        steps = []              # (ta, tb, dense) of the last two steps
        tails = {}              # per watch: the last sample before the step end (for dips)
        for ta, tb, dense in self.steps(slide, y0, t_stop):
            steps = (steps + [(ta, tb, dense)])[-2:]

            def evaluate(t, steps=steps):
                d = steps[-1][2] if (len(steps) == 1 or t >= steps[-1][0]) else steps[0][2]
                return None if d is None else d(t)

            found = self.roots_in_step(watches, ta, tb, dense, evaluate, tails)
            self.record_samples(min([tr for tr, _ in found] + [tb]), slide, evaluate)
            if found:
                te = min(tr for tr, _ in found)
                horizon = te + SAME_INSTANT * (1.0 + abs(te))
                fired = [w for tr, w in found if tr <= horizon]
                if horizon > tb:       # a root just past the step end is the same instant
                    Y = None if dense is None else dense(horizon)[:, None]
                    fired += [w for w in watches if w not in fired and not w.divided
                              and w.values(np.array([horizon]), Y)[0] <= 0]
                self.advance_to(te, slide, evaluate(te))
                return fired
        self.advance_to(t_stop, slide, steps[-1][2](t_stop) if slide else None)
        return []

    def steps(self, slide, y0, t_stop):
        """Steps (ta, tb, dense output) to t_stop: DOP853's accepted steps for the sliding bodies,
        or plain time steps when nothing slides (the watches then depend on time alone)."""
        M = self.M
        if not slide:
            ta = self.t
            while ta < t_stop:
                tb = min(ta + M.h_time, t_stop)
                yield ta, tb, None
                ta = tb
            return
        sgn = [self.sgn[b[0]] for b in slide]

        def rhs(t, y):
            out = np.empty_like(y)
            for i, b in enumerate(slide):
                out[2 * i] = y[2 * i + 1]
                out[2 * i + 1] = M.accel(b, t, y[2 * i], y[2 * i + 1], sgn[i])
            return out

        solver = DOP853(rhs, self.t, y0, t_stop, rtol=self.rtol, atol=self.atol,
                        max_step=M.h_max)
        while solver.status == "running":
            ta = solver.t
            msg = solver.step()
            if solver.status == "failed":
                raise Unsupported("integrator failed at t = %.17g: %s" % (ta, msg))
            yield ta, solver.t, solver.dense_output()

    @staticmethod
    def roots_in_step(watches, ta, tb, dense, evaluate, tails):
        """First root of every watch that has one in the step [ta, tb], as (t, watch) pairs.

        dense is the step's dense output (None when nothing slides); evaluate(t) gives the state
        at a time of this step or of the one before (a dip may straddle their border)."""
        ts = np.linspace(ta, tb, SAMPLES + 1)
        Ys = None if dense is None else dense(ts)
        found = []
        for w in watches:
            vs = w.values(ts, Ys)
            tt, vv = ts, vs
            if w in tails:
                tt = np.concatenate(([tails[w][0]], ts))
                vv = np.concatenate(([tails[w][1]], vs))
            tails[w] = (ts[-2], vs[-2])

            def scalar(t, w=w):
                Y = evaluate(t)
                return float(w.values(np.array([t]), None if Y is None else Y[:, None])[0])

            br = first_root(tt, vv, scalar)
            if br is not None:
                found.append((refine_root(scalar, br[0], br[1], w.t0), w))
        return found

    def record_samples(self, upto, slide, evaluate):
        """The state at the requested sample times up to `upto` (within the current motion)."""
        while self.sample_times and self.sample_times[-1] <= upto:
            t = self.sample_times.pop()
            phi, dphi = list(self.phi), list(self.dphi)
            y = evaluate(t) if slide else None
            for i, b in enumerate(slide):
                for p in b:
                    phi[p] = float(y[2 * i]) + (self.phi[p] - self.phi[b[0]])
                    dphi[p] = float(y[2 * i + 1])
            self.samples.append({"t": t, "phi": phi, "dphi": dphi})

    def advance_to(self, t, slide, y):
        self.t = t
        for i, b in enumerate(slide):
            self.set_body(b, float(y[2 * i]), float(y[2 * i + 1]))

    # ---- one instant ---------------------------------------------------------------------------

    def touching(self, k):
        i = self.order[k]
        return self.bond[k] or (self.gap(k) <= TOUCH * (1.0 + abs(self.phi[i]))
                                and not self.limiter_between(k))

    def limiter_between(self, k):
        """An armed limiter acting on both pellets of gap k separates them: it lies strictly
        inside the gap, or at one end with the pellet there on the far side of it."""
        i, j = self.gap_pellets(k)
        end = self.phi[j] + TWO_PI * self.wind[k]
        ulps = 4 * ON_LIMITER * (1 + abs(end))
        for li, L in enumerate(self.M.lims):
            if not self.armed[li] or i not in L.acts or j not in L.acts:
                continue
            if unwrap_ahead(L.theta, self.phi[i], +1) < end - ulps:
                return True
            ci, cj = self.on_limiter(i), self.on_limiter(j)
            side_i = ci[1] if ci is not None and ci[0] == li else 0
            side_j = cj[1] if cj is not None and cj[0] == li else 0
            if (side_i < 0 and side_j >= 0) or (side_j > 0 and side_i <= 0):
                return True
        return False

    def snap(self, anchors):
        """Put touching neighbours onto one place, starting from the bodies of the anchor pellets
        (those put onto a limiter, and bodies at rest), so that those stay where they are."""
        n = self.M.n
        if n < 2:
            return
        bodies = self.bodies()
        body_at = {p: b for b in bodies for p in b}
        fixed = {body_at[p] for p in anchors}
        changed = True
        while changed:
            changed = False
            for k in range(n):
                if self.bond[k] or not self.touching(k):
                    continue
                i, j = self.order[k], self.order[(k + 1) % n]
                bi, bj = body_at[i], body_at[j]
                if bi == bj:
                    continue
                if bi in fixed and bj not in fixed:
                    self.set_body(bj, self.phi[bj[0]] - self.gap(k), self.dphi[bj[0]])
                    fixed.add(bj)
                    changed = True
                elif bj in fixed and bi not in fixed:
                    self.set_body(bi, self.phi[bi[0]] + self.gap(k), self.dphi[bi[0]])
                    fixed.add(bi)
                    changed = True
            if not changed:
                for k in range(n):
                    if self.bond[k] or not self.touching(k):
                        continue
                    bi = body_at[self.order[k]]
                    bj = body_at[self.order[(k + 1) % n]]
                    if bi != bj and bi not in fixed and bj not in fixed:
                        fixed.add(bi)
                        changed = True
                        break

    def clusters(self):
        """Groups of pellets joined by touching gaps, each as a chain behind -> ahead."""
        n = self.M.n
        if n < 2:
            return [[0]]
        touch = [self.touching(k) for k in range(n)]
        if all(touch):
            raise Unsupported("all pellets touch around the whole circle")
        start = [k for k in range(n) if not touch[(k - 1) % n]]
        out = []
        for k in start:
            chain = [self.order[k]]
            while touch[k % n]:
                k += 1
                chain.append(self.order[k % n])
            out.append(chain)
        return out

    def gap_after(self, i):
        """Index of the gap from pellet i to its neighbour ahead."""
        return self.order.index(i)

    def impact_limiter(self, p, li):
        L = self.M.lims[li]
        before = self.dphi[p]
        after = -L.k * before
        self.dphi[p] = after
        self.emit("limiter", [p], li, [before], [after])
        if L.mobile:
            self.armed[li] = False
        for lj, Lj in enumerate(self.M.lims):
            if Lj.mobile and Lj.rearm_by == li:
                self.armed[lj] = True

    def impact_pair(self, i, j):
        m, kc = self.M.m, self.M.k_c
        vi, vj = self.dphi[i], self.dphi[j]
        mi, mj = m[i], m[j]
        self.dphi[i] = ((mi - kc * mj) * vi + mj * (1 + kc) * vj) / (mi + mj)
        self.dphi[j] = ((mj - kc * mi) * vj + mi * (1 + kc) * vi) / (mi + mj)
        self.emit("collision", [i, j], None, [vi, vj], [self.dphi[i], self.dphi[j]])

    def resolve(self, chain):
        """Impacts of one cluster at this instant, sweep after sweep (MODEL.md's order).

        Returns the pellets that took a limiter impact (for the chatter test), or raises."""
        M = self.M
        contacts = sorted((p, self.contact[p][0]) for p in chain if self.on_limiter(p))
        pairs = [(chain[q], chain[q + 1]) for q in range(len(chain) - 1)]
        v_start = [self.dphi[p] for p in chain]
        armed_start = list(self.armed)
        n_events = len(self.events)
        hit = set()
        impacts = 0
        for _ in range(MAX_SWEEPS):
            moved = False
            for p, li in contacts:
                side = self.contact[p][1]
                if self.armed[li] and p in M.lims[li].acts and side * self.dphi[p] < 0:
                    self.impact_limiter(p, li)
                    hit.add(p)
                    moved = True
                    impacts += 1
            for i, j in pairs:
                if self.dphi[i] > self.dphi[j] and not self.limiter_between(self.gap_after(i)):
                    self.impact_pair(i, j)
                    moved = True
                    impacts += 1
            if not moved:
                return hit
        # No sweep without impacts among the first MAX_SWEEPS: the cascade is replaced by its
        # limit, one plastic impact of the group (docs/MODEL.md), listed as one event.
        del self.events[n_events:]
        self.armed = armed_start
        if any(M.lims[li].mobile for _, li in contacts):
            raise Unsupported("a cascade of impacts involves a mobile limiter")
        mass = sum(M.m[p] for p in chain)
        V = sum(M.m[p] * v for p, v in zip(chain, v_start)) / mass
        stop = None
        for p, li in contacts:
            if self.armed[li] and p in M.lims[li].acts and self.contact[p][1] * V < 0:
                stop = li
        if stop is not None:
            V = 0.0
        for p in chain:
            self.dphi[p] = V
        self.emit("collision", chain, stop, v_start, [V] * len(chain), impacts_resolved=impacts)
        return set()

    def groups(self, run, wall_behind=False, wall_ahead=False):
        """Pool-adjacent-violators on the free accelerations of a run of touching pellets
        (behind -> ahead): a group behind that would accelerate at least as fast as the group
        ahead pushes it, and the two move as one.  A limiter that the run rests against is a
        group of its own that does not move (acceleration 0, infinite mass): the pellets pressed
        toward it join it.  An exact tie (no forces) joins; a near tie is decided by the time
        derivative, so a pair that has just started to pull apart stays apart.  Returns the
        groups as lists of pellets (the limiter's group without the limiter)."""
        M = self.M
        phi = self.phi[run[0]]

        def accel(block, deriv):
            ps, wall = block
            if wall:
                return 0.0
            f = 0.0
            for p in ps:
                if M.F0[p] != 0.0:
                    x = M.Om[p] * self.t + M.psi[p]
                    f += M.F0[p] * (-M.Om[p] * math.sin(x) if deriv else math.cos(x))
            f /= sum(M.m[p] for p in ps) * M.R
            return f if deriv else f - M.w * math.sin(phi)

        scale = M.w + sum(abs(M.F0[p]) / (M.m[p] * M.R) for p in run)
        dscale = sum(abs(M.F0[p] * M.Om[p]) / (M.m[p] * M.R) for p in run)

        def pushes(behind, ahead):
            d = accel(behind, False) - accel(ahead, False)
            if abs(d) > 1e-12 * scale:
                return d > 0
            return not accel(behind, True) - accel(ahead, True) < -1e-12 * dscale

        blocks = [([], True)] if wall_behind else []
        for p in run + ([None] if wall_ahead else []):
            blocks.append(([], True) if p is None else ([p], False))
            while len(blocks) > 1 and pushes(blocks[-2], blocks[-1]):
                ahead = blocks.pop()
                blocks[-1] = (blocks[-1][0] + ahead[0], blocks[-1][1] or ahead[1])
        return [ps for ps, _ in blocks if ps]

    def regroup(self, chain):
        """Bodies within a cluster of touching pellets (docs/MODEL.md): neighbours whose speeds
        agree and that the forces press together move as one body (see groups).

        For pellets at rest this is also Coulomb's law: a pressed pair can be held together
        exactly when its mean free acceleration is within the static friction, and a pair
        pulled apart cannot hold each other."""
        M = self.M
        for q in range(len(chain) - 1):
            self.bond[self.gap_after(chain[q])] = False
        scale = max([math.sqrt(M.w)] + [abs(self.dphi[p]) for p in chain])
        runs, cur = [], [chain[0]]
        for p in chain[1:]:
            if abs(self.dphi[p] - self.dphi[cur[-1]]) <= SPEED_AGREE * scale \
                    and not self.limiter_between(self.gap_after(cur[-1])):
                cur.append(p)
            else:
                runs.append(cur)
                cur = [p]
        runs.append(cur)
        for run in runs:
            if len(run) == 1:
                continue
            wall_behind = wall_ahead = False
            if abs(self.dphi[run[0]]) <= SPEED_AGREE * scale:
                first, last = self.limiter_contact((run[0],)), self.limiter_contact((run[-1],))
                wall_behind = first is not None and first[1] > 0
                wall_ahead = last is not None and last[1] < 0
            for ps in self.groups(run, wall_behind, wall_ahead):
                self.join(ps)
        self.join_chatter(chain)

    def join_chatter(self, chain):
        """Join pellets whose chatter against each other would end within the chatter time, or
        whose flights apart would stay within the round-off of the gap.

        The touching pellets that the forces press into one group (see groups, whatever their
        speeds) bounce on each other with k_c; across every cut of the group the part ahead
        separates from the part behind at w (difference of their mean speeds) and is pressed
        back at p (difference of their mean free accelerations), so the chatter left there
        lasts 2 w / (p (1 - k_c)), and the parts fly apart by w^2 / (2 p) at most.  When at every
        cut the chatter is shorter than the chatter time or the flight within FLIGHT, the group
        moves on as one body.  For two pellets this is the pair's own chatter; a third pellet
        pushing on a pair is what presses the pair together."""
        M = self.M

        def mean(ps, values):
            return sum(M.m[p] * values[p] for p in ps) / sum(M.m[p] for p in ps)

        force = {p: float(M.force([p], self.t)) / (M.m[p] * M.R) for p in chain}
        for group in self.groups(chain):
            cuts = [q for q in range(len(group) - 1) if not self.bond[self.gap_after(group[q])]]
            if not cuts or any(self.limiter_between(self.gap_after(group[q])) for q in cuts):
                continue
            flight = FLIGHT * (1.0 + max(abs(self.phi[p]) for p in range(M.n)))

            def bounded(q):
                behind, ahead = group[:q + 1], group[q + 1:]
                w = abs(mean(ahead, self.dphi) - mean(behind, self.dphi))
                press = mean(behind, force) - mean(ahead, force)
                if press <= 0:
                    return False
                chatter = math.inf if M.k_c >= 1.0 else 2 * w / (press * (1 - M.k_c))
                return chatter < M.chatter_time or w * w / (2 * press) <= flight

            if all(bounded(q) for q in cuts):
                self.join(group)

    def join(self, ps):
        """Bond touching pellets ps (a chain) into one body moving with their common momentum."""
        M = self.M
        v = sum(M.m[p] * self.dphi[p] for p in ps) / sum(M.m[p] for p in ps)
        for q in range(len(ps) - 1):
            self.bond[self.gap_after(ps[q])] = True
        for p in ps:
            self.dphi[p] = v

    def chatter_test(self, p, v_in, first_event):
        """After a limiter impact: sum the rest of a chatter series once it is short.

        A lone pellet meets the limiter's k at every impact of the series.  A body does too, at
        the fraction of its speed it left with this time, when it came in as one (its members
        at one speed) and this instant's collisions stayed among its members: the cascade is
        linear in the speed, so every later impact repeats it."""
        M = self.M
        body = self.body_of(p)
        c = self.on_limiter(p)
        if c is None or (self.pending is not None and self.pending[1] == body):
            return
        li, side, th = c
        L = M.lims[li]
        u = self.dphi[p]
        if L.mobile or not self.armed[li] or side * u <= 0 or self.touching_outside(body):
            return
        k = L.k
        if len(body) > 1:
            for ev in self.events[first_event:]:
                inside = [q in body for q in ev["pellets"]]
                if any(inside) and not all(inside):
                    return
            if any(v_in[q] != v_in[body[0]] for q in body) or v_in[body[0]] == 0.0:
                return
            k = -u / v_in[body[0]]
        press = -side * float(M.a_free(body, self.t, th))
        if press <= float(M.capacity(th)):
            return                      # static friction holds it once it stops: no chatter
        f = M.kinetic_friction_at_rest(th)
        a_away, a_toward = press + f, press - f
        if a_away <= 0 or a_toward <= 0:
            return
        r = k * math.sqrt(a_toward / a_away)
        if r >= 1.0:
            return
        T = abs(u) / a_away + abs(u) / math.sqrt(a_away * a_toward)
        if T / (1.0 - r) < M.chatter_time:
            self.pending = (self.t + T / (1.0 - r), body, li, u)
            for q in body:
                self.dphi[q] = 0.0
            self.set_mode(body, "rest")

    def touching_outside(self, body):
        """Whether the body touches a pellet outside it."""
        n = self.M.n
        if n < 2 or len(body) == n:
            return False
        first, last = self.order.index(body[0]), self.order.index(body[-1])
        return self.touching(last) or self.touching((first - 1) % n)

    def instant(self, fired):
        """Resolve everything that happens at self.t: snap the crossings onto their events, the
        impacts cluster by cluster, then the bodies and modes of whatever the instant touched."""
        M = self.M
        if self.pending is not None:
            for w in fired:
                if w.kind == "gap" and set(self.pending[1]) & set(self.gap_pellets(w.data["gap"])):
                    raise Unsupported("a pellet reaches pellet %d during its summed chatter"
                                      % self.pending[1][0])
        involved, reversed_, released, anchors = set(), set(), [], []
        v_in, first_event = list(self.dphi), len(self.events)
        for w in fired:
            if w.kind == "reversal":
                self.set_body(w.data["body"], self.phi[w.data["body"][0]], 0.0)
                reversed_.update(w.data["body"])
                anchors += self.turn_on_limiter(w.data["body"])
            elif w.kind == "release":
                released.append(w.data["body"])
            elif w.kind == "limiter":
                b, p = w.data["body"], w.data["pellet"]
                self.set_body(b, self.phi[b[0]] + (w.data["theta"] - self.phi[p]),
                              self.dphi[b[0]])
                self.phi[p] = w.data["theta"]
                anchors.append(p)
                if self.shielded(p, w.data["limiter"], w.data["side"]):
                    self.contact[p] = None       # it meets the pellet resting there instead
                else:
                    self.contact[p] = (w.data["limiter"], w.data["side"], w.data["theta"])
            if w.kind == "gap":
                involved.update(self.gap_pellets(w.data["gap"]))
            else:
                involved.update(w.data["body"])
        still = {p for p in range(M.n) if self.mode[p] != "slide"}
        self.snap(anchors + sorted(still))
        touched, hits = set(), []
        for chain in self.clusters():
            n_before = len(self.events)
            hit = self.resolve(chain)
            if len(self.events) > n_before:
                touched.update(chain)
                hits += sorted(hit)
        involved |= touched
        for chain in self.clusters():
            if len(chain) > 1 and involved.intersection(chain):
                self.regroup(chain)
        for p in hits:
            self.chatter_test(p, v_in, first_event)
        for b in self.bodies():
            if not involved.intersection(b) or (self.pending and self.pending[1] == b):
                continue
            if touched.intersection(b):
                cause = None
            elif b in released:
                cause = "release"
            elif reversed_.intersection(b):
                cause = "reversal"
            elif still.issuperset(b):
                cause = "start"
            else:
                cause = None
            self.settle(b, cause)

    def turn_on_limiter(self, body):
        """A body that turns back within round-off of a limiter is put on it.

        This is where a chatter that is not summed (several pellets bouncing together) ends:
        its flights shrink until the turning point is a few ulps from the limiter, where the
        next limiter ahead could no longer be told from the one just left.  A body that is
        pulled away from the limiter (a grazing approach) is left where it turned.  Returns the
        pellets put onto a limiter."""
        s_before = self.sgn[body[0]]
        for li, L in enumerate(self.M.lims):
            if not self.armed[li]:
                continue
            th = unwrap_near(L.theta, self.phi[body[0]])
            d = self.phi[body[0]] - th
            if abs(d) > TURNS_ON_LIMITER * (1 + abs(th)):
                continue
            left = [self.left[q][1] for q in body if self.left[q] is not None
                    and self.left[q][0] == li and self.left[q][2] == th]
            if abs(d) > 4 * ON_LIMITER * (1 + abs(th)):
                side = 1 if d > 0 else -1
            elif left:
                side = left[0]                  # back at the limiter it has just left
            else:
                side = -s_before                # it came up to the limiter and turned
            p = body[0] if side > 0 else body[-1]   # the end of the body facing the limiter
            if p not in L.acts:
                continue
            if side * float(self.M.a_free(body, self.t, th)) > float(self.M.capacity(th)):
                return []                       # pulled away: it just slides off (grazing)
            self.set_body(body, self.phi[body[0]] - d, 0.0)
            self.phi[p] = th
            self.contact[p] = None if self.shielded(p, li, side) else (li, side, th)
            return [p]
        return []

    def shielded(self, p, li, side):
        """Whether a pellet already rests against limiter li on this side, between p and it."""
        n = self.M.n
        q = p
        for _ in range(n - 1):
            k = self.order.index(q)
            if side > 0:                 # the limiter is behind p: look at the neighbour behind
                k = (k - 1) % n
                q = self.order[k]
            else:
                q = self.order[(k + 1) % n]
            if not self.touching(k):
                return False
            c = self.on_limiter(q)
            if c is not None and c[0] == li and c[1] == side:
                return True
        return False

    def gap_pellets(self, k):
        return self.order[k], self.order[(k + 1) % self.M.n]

    def initial_instant(self):
        """Modes at t = 0; pellets that start touching are resolved like an instant."""
        for p in range(self.M.n):
            for li, L in enumerate(self.M.lims):
                th = unwrap_near(L.theta, self.phi[p])
                if p in L.acts and abs(self.phi[p] - th) <= TOUCH * (1 + abs(th)):
                    raise Unsupported("pellet %d starts on limiter %d: its side is not defined"
                                      % (p, li))
        self.snap([])
        for chain in self.clusters():
            self.resolve(chain)
            if len(chain) > 1:
                self.regroup(chain)
        for b in self.bodies():
            self.settle(b, None)

    # ---- the run -------------------------------------------------------------------------------

    def run(self):
        M = self.M
        unsupported = None
        try:
            self.initial_instant()
            last_t, same = None, 0
            while self.t < M.t_end:
                t_stop = M.t_end if self.pending is None else min(M.t_end, self.pending[0])
                fired = self.scan(t_stop)
                if not fired:
                    if self.pending is not None and self.t >= self.pending[0]:
                        _, body, li, u = self.pending
                        self.pending = None
                        self.emit("chatter", body, li, [u] * len(body), [0.0] * len(body))
                    continue
                if last_t is not None and self.t <= last_t + SAME_INSTANT * (1 + abs(last_t)):
                    same += 1
                    if same > MAX_SAME_INSTANT:
                        raise Unsupported("the run does not leave the instant t = %.17g" % self.t)
                else:
                    last_t, same = self.t, 0
                self.instant(fired)
        except Unsupported as e:
            unsupported = str(e)
        return self.result(unsupported)

    def result(self, unsupported):
        final = []
        for p in range(self.M.n):
            state = STATE_NAMES[self.mode[p]]
            final.append({"phi": self.phi[p], "dphi": self.dphi[p] if state == "sliding" else 0.0,
                          "state": state})
        out = {"events": self.events, "final": final, "t_reached": self.t,
               "unsupported": unsupported}
        if self.samples:
            out["samples"] = self.samples
        return out


def simulate(scene, rtol=1e-12, atol=1e-14, samples=()):
    """Run a scene (a dict as in API.md) and return the result dict (see the module's doc).

    samples: times at which to record the state of every pellet as well, returned in
    result["samples"] as {"t", "phi": [...], "dphi": [...]} (for checks along the motion)."""
    return Sim(scene, rtol, atol, samples).run()


def main(argv):
    import argparse
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scene", help="scene JSON file, or - for stdin")
    ap.add_argument("--rtol", type=float, default=1e-12)
    ap.add_argument("--atol", type=float, default=1e-14)
    args = ap.parse_args(argv)
    text = sys.stdin.read() if args.scene == "-" else open(args.scene).read()
    try:
        res = simulate(json.loads(text), args.rtol, args.atol)
    except SceneError as e:
        print(json.dumps({"error": "bad scene: %s" % e}))
        return 2
    json.dump(res, sys.stdout, indent=1)
    print()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
