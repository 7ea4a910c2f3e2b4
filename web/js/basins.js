// The basins form of the sweep panel (API.md, "Added in the third round"; docs/SWEEPS.md,
// "Basins of attraction"): a 2-D sweep over two initial-state fields, each run labelled with the
// attractor it settles on, drawn as the basins image with a table of the attractors.

import { h } from "./dom.js";
import { checkField, numberField, readFields, selectField } from "./fields.js";
import { jobImage, jobJson, runJob } from "./jobs.js";
import { formatState, formatValue } from "./numbers.js";
import { parameterOptions, showUnitsOf } from "./parameters.js";
import { forcedPellet, parameterAxis, valueAt } from "./sweep.js";

// The fields a basin map may sweep: every pellet's φ₀ and φ̇₀.
export function initialStatePaths(scene) {
  return (scene.model?.pellets ?? []).flatMap((_, i) => [`model.pellets[${i}].phi0`, `model.pellets[${i}].dphi0`]);
}

// The angles a pellet starting at phi0 can reach before a limiter: (lo, hi) between the nearest
// copies (angle + 2πk) of the limiters' angles, (−∞, ∞) without limiters.
function between(scene, phi0) {
  let lo = -Infinity;
  let hi = Infinity;
  for (const l of scene.model?.limiters ?? []) {
    if (typeof l.angle !== "number") continue;
    const below = l.angle + 2 * Math.PI * Math.floor((phi0 - l.angle) / (2 * Math.PI));
    if (below < phi0) lo = Math.max(lo, below);
    hi = Math.min(hi, below + 2 * Math.PI);
  }
  return { lo, hi };
}

// A first basin map for a scene: its own, or the forced pellet's (φ₀, φ̇₀) over the angles it
// can reach within a quarter turn either way (0.01 rad short of a limiter, rounded inward to
// 0.01 rad) and speeds up to 2·sqrt(g/R).
export function defaultBasins(scene) {
  if (scene.sweep?.classify === "attractor") return { ...scene.sweep, parameter2: { ...scene.sweep.parameter2 } };
  const i = forcedPellet(scene);
  const phi0 = valueAt(scene, `model.pellets[${i}].phi0`) ?? 0;
  const { lo, hi } = between(scene, phi0);
  const from = Math.ceil(Math.max(lo + 0.01, phi0 - Math.PI / 2) * 100) / 100;
  const to = Math.floor(Math.min(hi - 0.01, phi0 + Math.PI / 2) * 100) / 100;
  const m = scene.model ?? {};
  const speed = Number((2 * Math.sqrt((m.g ?? 9.81) / (m.R ?? 1))).toPrecision(2));
  return {
    parameter: `model.pellets[${i}].phi0`,
    from,
    to,
    count: 40,
    parameter2: { parameter: `model.pellets[${i}].dphi0`, from: -speed, to: speed, count: 40 },
    transient: 100,
    record: 8,
  };
}

// One axis: the field swept, its range and its number of cells.
function axisRow(scene, path, axis, label) {
  const paths = initialStatePaths(scene);
  const field = selectField({ path: `${path}.parameter`, label, options: parameterOptions(paths), value: axis.parameter });
  const from = numberField({ path: `${path}.from`, label: "from", unit: "rad", value: axis.from });
  const to = numberField({ path: `${path}.to`, label: "to", unit: "rad", value: axis.to });
  const count = numberField({ path: `${path}.count`, label: "cells", value: axis.count });
  showUnitsOf(field.querySelector("select"), from, to);
  return [field, from, to, count];
}

// Fills `root` with the form for `scene`'s first basin map. Its inputs carry the sweep's field
// paths (data-field "sweep.from", ...), so a server error is shown next to its field; `root`
// itself stands for "sweep" as a whole.
export function fillBasinsForm(root, scene) {
  const b = defaultBasins(scene);
  root.dataset.field = "sweep";
  root.dataset.kind = "group";
  root.setAttribute("role", "group");
  root.setAttribute("aria-label", "Basin map");
  root.replaceChildren(
    h(
      "div",
      { class: "job-grid" },
      axisRow(scene, "sweep", b, "across (x)"),
      axisRow(scene, "sweep.parameter2", b.parameter2, "up (y)"),
      numberField({ path: "sweep.transient", label: "transient periods", value: b.transient }),
      numberField({ path: "sweep.record", label: "recorded periods", value: b.record }),
      checkField({ path: "sweep.classify", label: "classify attractors", checked: (b.classify ?? "attractor") === "attractor" }),
    ),
    h("p", { class: "field-error", hidden: true }),
  );
}

// The sweep the form asks for: { sweep, problems }.
export function readBasinsForm(root) {
  const { scene, problems } = readFields(root);
  const sweep = { ...scene.sweep, section: "stroboscopic", continuation: "none" };
  if (sweep.classify) sweep.classify = "attractor";
  return { sweep, problems };
}

// Runs the basin sweep as a job (jobs.js, runJob); resolves to {image, axis, attractors, cells}
// when done (axis: sweep.js, parameterAxis; attractors null when not classified), or null when
// cancelled.
export async function runBasins(scene, job, onProgress) {
  const at = await runJob("/api/sweep", scene, job, onProgress);
  if (!at) return null;
  const { image, response } = await jobImage(at);
  const attractors = scene.sweep.classify ? (await jobJson(at, "&part=summary")).attractors : null;
  return { image, axis: parameterAxis(response), attractors, cells: scene.sweep.count * scene.sweep.parameter2.count };
}

// The value of the cell at `k` of an axis's cells, as the sweep spaces them.
function cellValue(axis, k) {
  return axis.count > 1 ? axis.from + (k * (axis.to - axis.from)) / (axis.count - 1) : axis.from;
}

// The cell's index under `at`, a fraction 0 … 1 of the way across the cells (each cell centred
// on its value), or null outside them.
function cellIndex(axis, at) {
  if (at < 0 || at > 1) return null;
  return Math.min(axis.count - 1, Math.floor(at * axis.count));
}

// The start of the cell under a click at (x, y) in the image's own pixels: {x, y} values of
// the sweep's two fields, or null outside the map. `axis` is where the map lies (the
// parameter's axis across; the second parameter runs up the same plot area).
export function clickedStart(axis, sweep, x, y) {
  if (!axis) return null;
  const i = cellIndex(sweep, (x - axis.left) / axis.width);
  const j = cellIndex(sweep.parameter2, (axis.top + axis.height - y) / axis.height);
  if (i === null || j === null) return null;
  return { x: cellValue(sweep, i), y: cellValue(sweep.parameter2, j) };
}

const cell = (tag, text, attrs = {}) => h(tag, attrs, text);

// The attractor's states on the section, one "(φ, φ̇)" per period, "(φ₁, φ̇₁; φ₂, φ̇₂)" with two
// pellets (the section lists each period's state pellet by pellet); the rest attractor has none.
function sectionText(a) {
  if (a.at_rest)
    return 'at rest: every pellet held (by friction or on a limiter), wherever it rests';
  const pellets = Math.max(1, Math.round(a.section.length / Math.max(1, a.period)));
  const states = [];
  for (let k = 0; k < a.section.length; k += pellets) {
    const state = a.section.slice(k, k + pellets).map((s) => `${formatState(s.phi, 4)}, ${formatState(s.dphi, 4)}`);
    states.push(`(${state.join("; ")})`);
  }
  return states.join(", ");
}

// The attractors as a table: id (as in the image's legend), period, impacts per period, section
// points and cells; a last row for the cells that settled on none.
export function attractorTable(attractors, cells) {
  const percent = (n) => `${formatValue((100 * n) / cells, 3)} %`;
  const rows = attractors.map((a) =>
    h(
      "tr",
      {},
      cell("th", String(a.id), { scope: "row" }),
      cell("td", String(a.period)),
      cell("td", formatValue(a.impacts_per_period, 3)),
      cell("td", sectionText(a)),
      cell("td", String(a.cells)),
      cell("td", percent(a.cells)),
    ),
  );
  const settled = attractors.reduce((n, a) => n + a.cells, 0);
  if (settled < cells)
    rows.push(h("tr", { class: "none" }, cell("th", "—", { scope: "row" }), h("td", { colspan: 3 }, "not periodic within the record"), cell("td", String(cells - settled)), cell("td", percent(cells - settled))));
  const table = h(
    "table",
    { class: "attractors" },
    h("caption", {}, `${attractors.length} ${attractors.length === 1 ? "attractor" : "attractors"} over ${cells} starts`),
    h(
      "thead",
      {},
      h(
        "tr",
        {},
        ["attractor", "period (T)", "impacts per period", "section at t = kT: (φ rad, φ̇ rad/s) per pellet", "cells", "share"].map((t) => cell("th", t, { scope: "col" })),
      ),
    ),
    h("tbody", {}, rows),
  );
  // A long list (rest states of a pellet friction holds anywhere, say) scrolls in its own box.
  return rows.length > 12 ? h("div", { class: "scroll" }, table) : table;
}
