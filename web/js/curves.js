// Two-parameter curves in the periodic-motion panel (API.md, "Added in the third round";
// docs/ORBITS.md, "Two-parameter curves"): the motion's branch continued in one parameter, the
// first fold, period doubling or grazing on it followed in a second, run as a job and drawn as
// the bifurcation_curves figure, with the curves and the branch's bifurcations in words.

import { h } from "./dom.js";
import { numberField, readFields, selectField } from "./fields.js";
import { jobImage, jobJson, runJob } from "./jobs.js";
import { formatValue } from "./numbers.js";
import { parameterLabel, parameterName, parameterOptions, showUnitsOf, tidy, unitOf } from "./parameters.js";
import { defaultSweep, sweepablePaths, valueAt } from "./sweep.js";

export const FOLLOW_KINDS = [
  { value: "fold", label: "fold" },
  { value: "period_doubling", label: "period doubling" },
  { value: "grazing", label: "grazing" },
];
const KIND_NAMES = { fold: "fold", period_doubling: "period doubling", neimark_sacker: "Neimark–Sacker", grazing: "grazing" };

// A second parameter and its range: the first limiter's restitution k from 0.75k to
// min(1, 1.2k), or else the forced pellet's F₀ ± 50 %.
function defaultSecond(scene, first) {
  const k = scene.model?.limiters?.[0]?.k;
  if (typeof k === "number" && k > 0 && first !== "model.limiters[0].k")
    return { parameter: "model.limiters[0].k", from: tidy(0.75 * k), to: tidy(Math.min(1, 1.2 * k)) };
  const parameter = first.replace(/\.\w+$/, ".F0");
  const v = valueAt(scene, parameter) ?? 1;
  return { parameter, from: tidy(v / 2), to: tidy(v * 1.5) };
}

// A first two-parameter request for a scene: its own continuation (and follow), or the sweep
// panel's parameter from its value to 1.5 times it, a period doubling followed.
export function defaultFollow(scene) {
  const c = scene.periodic_orbit?.continuation ?? {};
  const parameter = c.parameter ?? defaultSweep(scene).parameter;
  const v = valueAt(scene, parameter) ?? 1;
  return {
    parameter,
    to: c.to ?? tidy(1.5 * v),
    max_points: c.max_points ?? 200,
    follow: c.follow ?? "period_doubling",
    parameter2: c.parameter2 ? { ...c.parameter2 } : defaultSecond(scene, parameter),
  };
}

// Fills `root` with the form for `scene`'s first request. Its inputs carry the request's field
// paths ("periodic_orbit.continuation.to", ...), so a server error is shown next to its field;
// `root` itself stands for "periodic_orbit" as a whole.
export function fillFollowForm(root, scene) {
  const f = defaultFollow(scene);
  const c = "periodic_orbit.continuation";
  const options = parameterOptions(sweepablePaths(scene));
  const first = selectField({ path: `${c}.parameter`, label: "continue in", options, value: f.parameter });
  const to = numberField({ path: `${c}.to`, label: "to", unit: "-", value: f.to });
  const second = selectField({ path: `${c}.parameter2.parameter`, label: "follow it in", options, value: f.parameter2.parameter });
  const from2 = numberField({ path: `${c}.parameter2.from`, label: "from", unit: "-", value: f.parameter2.from });
  const to2 = numberField({ path: `${c}.parameter2.to`, label: "to", unit: "-", value: f.parameter2.to });
  showUnitsOf(first.querySelector("select"), to);
  showUnitsOf(second.querySelector("select"), from2, to2);
  root.dataset.field = "periodic_orbit";
  root.dataset.kind = "group";
  root.setAttribute("role", "group");
  root.setAttribute("aria-label", "Two-parameter curves");
  root.replaceChildren(
    h(
      "div",
      { class: "job-grid" },
      first,
      to,
      numberField({ path: `${c}.max_points`, label: "at most points", value: f.max_points }),
      h("div", { class: "field" }),
      second,
      from2,
      to2,
      selectField({ path: `${c}.follow`, label: "bifurcation followed", options: FOLLOW_KINDS, value: f.follow }),
    ),
    h("p", { class: "field-error", hidden: true }),
  );
}

// The periodic_orbit request the form asks for, with the panel's periods and transient:
// { request, problems }.
export function readFollowForm(root, periods, transient) {
  const { scene, problems } = readFields(root);
  return { request: { periods, transient, continuation: scene.periodic_orbit?.continuation ?? {} }, problems };
}

// Runs the request as a job (jobs.js, runJob); resolves to {image, answer} when done, or null
// when cancelled. The job's progress counts thousandths of the way.
export async function runFollow(scene, job, onProgress) {
  const at = await runJob("/api/periodic-orbit", scene, job, onProgress);
  if (!at) return null;
  const [{ image }, answer] = await Promise.all([jobImage(at), jobJson(at)]);
  return { image, answer };
}

const range = (points, key) => {
  const values = points.map((p) => p[key]);
  return `${formatValue(Math.min(...values), 5)} … ${formatValue(Math.max(...values), 5)}`;
};

// The curves as a table (kind, points, the span of each parameter, how each direction ended),
// and the branch's bifurcations as a sentence.
export function describeCurves(answer, request) {
  const c = request.continuation;
  const p1 = parameterLabel(c.parameter);
  const p2 = parameterLabel(c.parameter2.parameter);
  const unit = unitOf(c.parameter);
  const found = answer.bifurcations ?? [];
  const at = (b) => `${KIND_NAMES[b.kind] ?? b.kind} at ${formatValue(b.value, 6)}${unit ? ` ${unit}` : ""}`;
  const branch = found.length
    ? `The branch continued in ${parameterName(c.parameter)} meets a ${found.map(at).join(", a ")}.`
    : `The branch continued in ${parameterName(c.parameter)} meets no bifurcation.`;
  const rows = (answer.curves ?? []).map((curve) =>
    h(
      "tr",
      {},
      h("th", { scope: "row" }, KIND_NAMES[curve.kind] ?? curve.kind),
      h("td", {}, String(curve.points.length)),
      h("td", {}, curve.points.length ? range(curve.points, "value") : "—"),
      h("td", {}, curve.points.length ? range(curve.points, "value2") : "—"),
      h("td", { class: "message" }, curve.message ?? ""),
    ),
  );
  const table = h(
    "table",
    { class: "curves" },
    h("caption", {}, `Curves followed in ${p2}`),
    h(
      "thead",
      {},
      h("tr", {}, ["curve", "points", p1, p2, "how it ended"].map((t) => h("th", { scope: "col" }, t))),
    ),
    h("tbody", {}, rows),
  );
  return [h("p", {}, branch), table];
}
