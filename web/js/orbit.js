// The periodic-motion panel: the scene's periodic motion on the stroboscopic section (API.md,
// "Periodic motions and their stability"), what it is in words, and a scene that starts on it.

import { postJson } from "./api.js";
import { formatState, formatValue } from "./numbers.js";

// POSTs the scene with its periodic_orbit request; resolves to the answer's JSON (a refusal is
// an ApiError naming its field).
export async function findOrbit(scene, request) {
  return (await postJson("/api/periodic-orbit", { ...scene, periodic_orbit: request })).json();
}

const digits = (x, n = 4) => (x === null || x === undefined ? "—" : formatValue(x, n));

function multiplier({ re, im }) {
  const size = Math.hypot(re, im);
  const value = Math.abs(im) < 1e-12 ? digits(re) : `${digits(re)} ${im < 0 ? "−" : "+"} ${digits(Math.abs(im))}i`;
  return `${value} (|μ| = ${digits(size)})`;
}

// The mobile limiters the section finds disarmed, in words ("" if none).
function disarmed(o) {
  const off = (o.armed ?? []).flatMap((armed, l) => (armed ? [] : [`limiter ${l + 1}`]));
  return off.length ? `; ${off.join(' and ')} disarmed` : '';
}

// A motion's stability as a sentence starts: neutral when a multiplier lies on the unit circle
// within the tolerance (an area-preserving motion), neither stable nor unstable.
function stability(o) {
  if (o.stable) return 'A stable';
  return o.neutral ? 'A neutral' : 'An unstable';
}

// Lines that say what was found, for a person: whether it is a motion, stable or not, its
// multipliers and impacts, and what the checks said.
export function describeOrbit(answer) {
  const o = answer.orbit;
  if (!o.converged) return [`No periodic motion found: ${o.message}`];
  if (o.at_rest)
    return [
      `From this start the scene comes to rest by t = ${digits(o.t0)} s: ${
          o.state.map((s, i) => `pellet ${i + 1} at φ = ${formatState(s.phi)} rad`)
              .join(
                  ', ')}. A rest state repeats with every period, but it is no vibro-impact motion.`,
      'Other starts may reach a periodic motion: change the pellets\' φ0 and φ̇0 (or the transient) and search again. docs/ORBITS.md shows the paper scene\'s period-6 motion, reached from another start.',
    ];
  const n = o.periods === 1 ? "period-1" : `period-${o.periods}`;
  const lines = [
    `${stability(o)} ${n} motion with ${digits(o.impacts_per_period, 3)} ${
        o.impacts_per_period === 1 ? 'impact' : 'impacts'} per forcing period (T = ${
        digits(o.period)} s), returning within ${digits(o.residual, 2)}.`,
    `State at t = ${digits(o.t0)} s: ${
        o.state
            .map(
                (s, i) => `pellet ${i + 1} φ = ${formatState(s.phi)} rad, φ̇ = ${
                    formatState(s.dphi)} rad/s`)
            .join('; ')}${disarmed(o)}.`,
    `Floquet multipliers: ${o.multipliers.map(multiplier).join(', ')}${
        o.exact_jacobian ? '' : ` (${o.jacobian_note})`}.`,
  ];
  lines.push(o.admissible ? "Checked as a physical motion: a tighter run returns to it and vouches for its events." : `Not vouched for: ${o.message}`);
  return lines;
}

// The scene started on the motion's state, run for one return: its portrait is the closed orbit.
export function sceneOnOrbit(scene, answer) {
  const o = answer.orbit;
  const out = structuredClone(scene);
  o.state.forEach((s, i) => {
    out.model.pellets[i].phi0 = s.phi;
    out.model.pellets[i].dphi0 = s.dphi;
  });
  // A mobile limiter starts as the section finds it: disarmed where the motion has passed it.
  (o.armed ?? []).forEach((armed, l) => {
    const limiter = out.model.limiters?.[l];
    if (!limiter?.mobile) return;
    if (armed)
      delete limiter.armed;
    else
      limiter.armed = false;
  });
  // t0 is a whole number of periods of every force, so the forces' phases are as at t = 0.
  out.t_end = o.periods * o.period;
  delete out.periodic_orbit;
  return out;
}
