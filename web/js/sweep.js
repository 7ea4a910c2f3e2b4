// The sweep panel: a parameter of the scene swept over a range as a server job (API.md,
// "Sweeps"), its progress, cancel, the diagram, and the parameter value under a click on it.

import { jobImage, runJob } from "./jobs.js";
import { tidy } from "./parameters.js";
import { parsePath } from "./scene_path.js";

// The numeric fields of a scene that a sweep can vary, as paths.
export function sweepablePaths(scene) {
  const m = scene.model ?? {};
  const paths = [];
  (m.pellets ?? []).forEach((p, i) => {
    for (const f of ["F0", "Omega", "psi", "c", "m", "phi0", "dphi0"]) paths.push(`model.pellets[${i}].${f}`);
  });
  (m.limiters ?? []).forEach((_, j) => {
    for (const f of ["k", "angle"]) paths.push(`model.limiters[${j}].${f}`);
  });
  paths.push("model.R", "model.alpha0", "model.k_c", "model.g");
  return paths;
}

export function valueAt(scene, path) {
  let node = scene;
  for (const key of parsePath(path) ?? []) node = node?.[key];
  return typeof node === "number" ? node : undefined;
}

// The index of the first forced pellet (Ω > 0 and F0 ≠ 0), or 0 when none is.
export function forcedPellet(scene) {
  const pellets = scene.model?.pellets ?? [];
  return Math.max(0, pellets.findIndex((p) => (p.Omega ?? 0) > 0 && (p.F0 ?? 0) !== 0));
}

// A first sweep for a scene: its own, or the first forced pellet's Ω around its value.
export function defaultSweep(scene) {
  if (scene.sweep) return { ...scene.sweep };
  const pellets = scene.model?.pellets ?? [];
  const i = forcedPellet(scene);
  const parameter = pellets[i] && (pellets[i].Omega ?? 0) > 0 ? `model.pellets[${i}].Omega` : `model.pellets[0].F0`;
  const v = valueAt(scene, parameter) ?? 1;
  return { parameter, from: tidy(v / 2), to: tidy(v * 1.5), count: 100, transient: 50, record: 20, section: "stroboscopic", continuation: "none" };
}

// Runs the sweep as a job: onProgress({done, total}) while it runs; resolves to
// {image: Blob, axis: {left, top, width, height, from, to} | null, id} when done, or null when
// cancelled through `job.cancel()` (job: an object this fills with cancel()).
export async function runSweep(scene, job, onProgress) {
  const at = await runJob("/api/sweep", scene, job, onProgress);
  if (!at) return null;
  const { image, response } = await jobImage(at);
  return { image, axis: parameterAxis(response), id: at.slice("/api/jobs/".length) };
}

// Where a sweep image's plot area lies and the parameter's span across it (the server's
// X-Vibro-Parameter-Axis): {left, top, width, height, from, to} in the image's own pixels, or null.
export function parameterAxis(response) {
  const header = response.headers.get("X-Vibro-Parameter-Axis");
  if (!header) return null;
  const [left, top, width, height, from, to] = header.split(",").map(Number);
  return { left, top, width, height, from, to };
}

// The parameter value under a click at (x, y) in the image's own pixels, or null outside the
// plot area.
export function clickedValue(axis, x, y) {
  if (!axis || x < axis.left || x > axis.left + axis.width || y < axis.top || y > axis.top + axis.height) return null;
  return axis.from + ((x - axis.left) / axis.width) * (axis.to - axis.from);
}
