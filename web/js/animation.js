// The run animated: the mechanism (circle, limiters, pellets, force arrows) drawn at a time t on a
// canvas, and markers over the figure at the same t (each pellet's state on its phase portrait,
// a line at t on φ(t)), with play/pause and a time slider. The sampled trajectory comes from the
// server as CSV (API.md, "Exports"), fetched once per run when the animation is first used.

import { plotPoint } from "./api.js";

// The figures' series colours (render/style.h), so a pellet has one colour everywhere.
const COLOURS = ["#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#F0E442", "#000000"];

// {pellet: [{t, phi, dphi}, …] in time order} from the trajectory CSV (t,pellet,branch,phi,dphi).
export function parseTrajectory(csv) {
  const byPellet = new Map();
  for (const line of csv.trim().split("\n").slice(1)) {
    const [t, pellet, , phi, dphi] = line.split(",").map(Number);
    if (!byPellet.has(pellet)) byPellet.set(pellet, []);
    byPellet.get(pellet).push({ t, phi, dphi });
  }
  for (const samples of byPellet.values()) samples.sort((a, b) => a.t - b.t);
  return byPellet;
}

// The state of a pellet at t, linear between samples; held at the ends.
export function stateAt(samples, t) {
  if (!samples?.length) return null;
  if (t <= samples[0].t) return samples[0];
  const last = samples[samples.length - 1];
  if (t >= last.t) return last;
  let lo = 0;
  let hi = samples.length - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (samples[mid].t <= t) lo = mid;
    else hi = mid;
  }
  const a = samples[lo];
  const b = samples[hi];
  const w = b.t > a.t ? (t - a.t) / (b.t - a.t) : 0;
  return { t, phi: a.phi + w * (b.phi - a.phi), dphi: a.dphi + w * (b.dphi - a.dphi) };
}

function arrow(ctx, x0, y0, x1, y1) {
  const angle = Math.atan2(y1 - y0, x1 - x0);
  ctx.beginPath();
  ctx.moveTo(x0, y0);
  ctx.lineTo(x1, y1);
  ctx.stroke();
  ctx.beginPath();
  ctx.moveTo(x1, y1);
  ctx.lineTo(x1 - 8 * Math.cos(angle - 0.4), y1 - 8 * Math.sin(angle - 0.4));
  ctx.lineTo(x1 - 8 * Math.cos(angle + 0.4), y1 - 8 * Math.sin(angle + 0.4));
  ctx.closePath();
  ctx.fill();
}

// The mechanism at t: φ from the lowest point, positive toward limiter 1's side (to the right).
export function drawMechanism(canvas, scene, trajectory, t) {
  const ctx = canvas.getContext("2d");
  const w = canvas.width;
  const h = canvas.height;
  ctx.clearRect(0, 0, w, h);
  const cx = w / 2;
  const cy = h / 2;
  const r = 0.36 * Math.min(w, h);
  const at = (phi, radius = r) => [cx + radius * Math.sin(phi), cy + radius * Math.cos(phi)];
  ctx.lineWidth = 2;
  ctx.strokeStyle = "#222";
  ctx.beginPath();
  ctx.arc(cx, cy, r, 0, 2 * Math.PI);
  ctx.stroke();
  ctx.fillStyle = "#222";
  ctx.font = "12px DejaVu Sans, sans-serif";
  ctx.textAlign = "center";
  ctx.fillText(`t = ${t.toFixed(3)} s`, cx, 16);
  (scene.model.limiters ?? []).forEach((l, j) => {
    const [x0, y0] = at(l.angle, r - 12);
    const [x1, y1] = at(l.angle, r + 12);
    ctx.setLineDash(l.mobile ? [4, 3] : []);
    ctx.lineWidth = 4;
    ctx.strokeStyle = "#555";
    ctx.beginPath();
    ctx.moveTo(x0, y0);
    ctx.lineTo(x1, y1);
    ctx.stroke();
    ctx.setLineDash([]);
    const [lx, ly] = at(l.angle, r + 26);
    ctx.fillStyle = "#555";
    ctx.fillText(`${j + 1}`, lx, ly + 4);
  });
  (scene.model.pellets ?? []).forEach((p, i) => {
    const s = stateAt(trajectory.get(i), t);
    if (!s) return;
    const [x, y] = at(s.phi);
    const colour = COLOURS[i % COLOURS.length];
    const F = p.F0 ? p.F0 * Math.cos((p.Omega ?? 0) * t + (p.psi ?? 0)) : 0;
    if (F) {
      // Tangential, along +φ for F > 0; its length grows with |F| up to a third of the radius.
      const scale = (r / 3) * (F / Math.abs(p.F0));
      ctx.strokeStyle = colour;
      ctx.fillStyle = colour;
      ctx.lineWidth = 2;
      arrow(ctx, x, y, x + scale * Math.cos(s.phi), y - scale * Math.sin(s.phi));
    }
    ctx.fillStyle = colour;
    ctx.beginPath();
    ctx.arc(x, y, 7, 0, 2 * Math.PI);
    ctx.fill();
    ctx.fillStyle = "#fff";
    ctx.fillText(`${i + 1}`, x, y + 4);
  });
}

// The markers over the figure at t: canvas is the image's overlay, sized to its natural pixels.
export function drawMarkers(canvas, plotAxes, trajectory, t) {
  const ctx = canvas.getContext("2d");
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  for (const a of plotAxes) {
    if (a.kind === "time") {
      if (t < a.x[0] || t > a.x[1]) continue;
      const { x } = plotPoint(a, t, a.y[0]);
      ctx.strokeStyle = "rgba(34,34,34,0.6)";
      ctx.lineWidth = 1.5;
      ctx.beginPath();
      ctx.moveTo(x, a.top);
      ctx.lineTo(x, a.top + a.height);
      ctx.stroke();
      continue;
    }
    const s = stateAt(trajectory.get(a.pellet), t);
    if (!s) continue;
    const { x, y } = plotPoint(a, s.phi, s.dphi);
    ctx.fillStyle = COLOURS[a.pellet % COLOURS.length];
    ctx.strokeStyle = "#fff";
    ctx.lineWidth = 2;
    ctx.beginPath();
    ctx.arc(x, y, 6, 0, 2 * Math.PI);
    ctx.fill();
    ctx.stroke();
  }
}
