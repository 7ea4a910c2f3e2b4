// The scene editor: one labelled input per scene field (API.md), built from a scene object and
// read back into one. Adding or removing pellets, limiters and panels reads the form, edits the
// scene object (renumbering every index that points at what moved) and rebuilds the form, so
// the DOM never holds state the scene object does not.

import { fill, h } from "./dom.js";
import { checkField, intListField, numberField, pelletChecks, pelletOptions, readFields, selectField, textField } from "./fields.js";

export const MAX_PELLETS = 8;
const MAX_LIMITERS = 16;
const MAX_PLOTS = 8;

const FRICTION_LAWS = [
  { value: "paper", label: "paper" },
  { value: "bilateral", label: "bilateral" },
];
const METHODS = [
  { value: "auto", label: "auto" },
  { value: "dopri5", label: "dopri5 (explicit, 5)" },
  { value: "dop853", label: "dop853 (explicit, 8)" },
  { value: "radau5", label: "radau5 (implicit, 5)" },
  { value: "taylor", label: "taylor (series, tight tolerances)" },
];
const PLOT_KINDS = [
  { value: "phase", label: "phase portrait", short: "Phase" },
  { value: "time", label: "time series", short: "Time" },
  { value: "cylinder", label: "cylinder (3-D)", short: "Cylinder" },
  { value: "mechanism", label: "mechanism (to scale)", short: "Mechanism" },
  { value: "work_precision", label: "work–precision", short: "Work–precision" },
];
const KIND_TITLES = { phase: "phase portrait", time: "time series", cylinder: "phase cylinder", mechanism: "mechanism", work_precision: "work–precision" };

export class SceneForm {
  // root: an element to fill; onEdit: called after any change made by the user.
  constructor(root, { onEdit }) {
    this.root = root;
    this.onEdit = onEdit;
    this.name = undefined;
    root.addEventListener("input", () => onEdit());
    root.addEventListener("change", () => onEdit());
  }

  load(scene) {
    this.name = scene.name;
    const model = scene.model ?? {};
    const n = model.pellets?.length ?? 0;
    fill(this.root,
      this.modelSection(model),
      this.pelletsSection(model.pellets ?? []),
      this.limitersSection(model.limiters ?? [], n),
      this.runSection(scene),
      this.plotsSection(scene.plots ?? [], n),
      this.imageSection(scene),
    );
  }

  // { scene, problems: [{field, message}] } (fields.js, readFields).
  read() {
    return readFields(this.root, this.name ? { name: this.name } : {});
  }

  // Rebuilds the form after `edit` changes the scene, then focuses `focusPath` if given.
  restructure(edit, focusSelector) {
    const { scene } = this.read();
    edit(scene);
    this.load(scene);
    this.onEdit();
    const target = focusSelector && this.root.querySelector(focusSelector);
    if (target) target.focus();
  }

  // [SECTION] model
  modelSection(m) {
    return section(
      "Model",
      grid(
        numberField({ path: "model.g", label: "g — gravity", unit: "m/s²", value: m.g, placeholder: "9.81" }),
        numberField({ path: "model.R", label: "R — radius", unit: "m", value: m.R }),
        numberField({ path: "model.alpha0", label: "α₀ — friction angle", unit: "rad", value: m.alpha0, placeholder: "0", hint: "μ = tan α₀" }),
        selectField({ path: "model.friction", label: "Friction law", value: m.friction ?? "paper", options: FRICTION_LAWS, hint: "bilateral: |N|, on a wire" }),
        numberField({ path: "model.mu_s", label: "μₛ — static coefficient", value: m.mu_s, placeholder: "tan α₀", hint: "≥ μ; for the stick test" }),
        numberField({ path: "model.k_c", label: "k_c — pellet restitution", value: m.k_c, placeholder: "1", hint: "0 plastic … 1 elastic" }),
      ),
    );
  }

  // [SECTION] pellets
  pelletsSection(pellets) {
    const n = pellets.length;
    const cards = pellets.map((p, i) => {
      const path = `model.pellets[${i}]`;
      const who = `Pellet ${i + 1}`;
      return card(
        path,
        who,
        removeButton(`Remove pellet ${i + 1}`, n <= 1, () => this.restructure((s) => removePellet(s, i), "[data-action=add-pellet]")),
        grid(
          numberField({ path: `${path}.m`, label: "m — mass", unit: "kg", value: p.m, aria: `${who} mass m (kg)` }),
          numberField({ path: `${path}.phi0`, label: "φ₀ — angle", unit: "rad", value: p.phi0, angle: true, aria: `${who} initial angle φ₀ (rad)` }),
          numberField({ path: `${path}.dphi0`, label: "φ̇₀ — velocity", unit: "rad/s", value: p.dphi0, placeholder: "0", aria: `${who} initial angular velocity φ̇₀ (rad/s)` }),
          numberField({ path: `${path}.F0`, label: "F₀ — force", unit: "N", value: p.F0, placeholder: "0", aria: `${who} force amplitude F₀ (N)` }),
          numberField({ path: `${path}.Omega`, label: "Ω — frequency", unit: "rad/s", value: p.Omega, placeholder: "0", aria: `${who} force frequency Ω (rad/s)` }),
          numberField({ path: `${path}.psi`, label: "ψ — phase", unit: "rad", value: p.psi, angle: true, placeholder: "0", aria: `${who} force phase ψ (rad)` }),
          numberField({ path: `${path}.c`, label: "c — damping", unit: "1/s", value: p.c, placeholder: "0", hint: "viscous, ≥ 0", aria: `${who} viscous damping c (1/s)` }),
        ),
      );
    });
    const add = addButton("pellet", "+ Pellet", n >= MAX_PELLETS, () =>
      this.restructure((s) => addPellet(s), `[data-field="model.pellets[${n}].m"]`),
    );
    return section(`Pellets (${n} of 1–${MAX_PELLETS})`, [
      h("p", { class: "note" }, "Force F(t) = F₀ cos(Ωt + ψ); damping adds −c·φ̇ to the acceleration. Angles from the lowest point, positive toward limiter 1; they accept π, e.g. π/12. A pellet started on a limiter's angle and moving strikes it at t = 0; to start it leaving the limiter, set φ₀ just off the angle."),
      cards,
      h("div", { class: "adders" }, add),
    ], { field: "model.pellets" });
  }

  // [SECTION] limiters
  limitersSection(limiters, pelletCount) {
    const n = limiters.length;
    const cards = limiters.map((l, i) => {
      const path = `model.limiters[${i}]`;
      const rearm = selectField({
        path: `${path}.rearm_by`,
        label: "re-armed by",
        kind: "int-optional",
        value: l.rearm_by,
        disabled: !l.mobile,
        options: [{ value: "", label: "—" }].concat(
          limiters.map((_, j) => ({ value: j, label: `limiter ${j + 1}` })).filter((o) => o.value !== i),
        ),
        hint: "impacts on it re-arm this one",
      });
      const rearmSelect = rearm.querySelector("select");
      // Only a mobile limiter may start disarmed (a scene started on a periodic motion's section).
      const armed = checkField({
        path: `${path}.armed`,
        label: 'armed at start',
        checked: l.armed !== false,
        defaultOn: true
      });
      const armedBox = armed.querySelector('input');
      armedBox.disabled = !l.mobile;
      return card(
          path,
          `Limiter ${i + 1}`,
          removeButton(
              `Remove limiter ${i + 1}`, false,
              () => this.restructure((s) => removeLimiter(s, i), '[data-action=add-limiter]')),
          grid(
              numberField({
                path: `${path}.angle`,
                label: 'angle',
                unit: 'rad',
                value: l.angle,
                angle: true,
                aria: `Limiter ${i + 1} angle (rad)`
              }),
              numberField({
                path: `${path}.k`,
                label: 'k — restitution',
                value: l.k,
                hint: '[0, 1]',
                aria: `Limiter ${i + 1} restitution k`
              }),
              checkField({
                path: `${path}.mobile`,
                label: 'mobile',
                checked: l.mobile,
                onChange: (e) => {
                  rearmSelect.disabled = !e.target.checked;
                  armedBox.disabled = !e.target.checked;
                },
              }),
              rearm,
              armed,
              pelletChecks({
                path: `${path}.pellets`,
                legend: `Limiter ${i + 1} acts on pellets`,
                count: pelletCount,
                selected: l.pellets ?? [],
                hint: 'none checked: all pellets',
              }),
              ),
      );
    });
    const add = addButton("limiter", "+ Limiter", n >= MAX_LIMITERS, () =>
      this.restructure((s) => (s.model.limiters ??= []).push({ angle: Math.PI / 4, k: 0.5 }), `[data-field="model.limiters[${n}].angle"]`),
    );
    return section(`Limiters (${n})`, [
      h("p", { class: "note" }, "A mobile limiter is disarmed by the impact it takes and re-armed by an impact on the limiter named."),
      cards,
      h("div", { class: "adders" }, add),
    ], { field: "model.limiters" });
  }

  // [SECTION] run
  runSection(scene) {
    const solver = scene.solver ?? {};
    return section(
      "Run",
      grid(
        numberField({ path: "t_end", label: "t_end — duration", unit: "s", value: scene.t_end }),
        selectField({ path: "solver.method", label: "Integrator", value: solver.method ?? "auto", options: METHODS, hint: "auto: DOP853, Radau IIA when stiff" }),
        numberField({ path: "solver.rtol", label: "rtol", value: solver.rtol, placeholder: "1e-9", hint: "relative tolerance" }),
        numberField({ path: "solver.atol", label: "atol", value: solver.atol, placeholder: "1e-12", hint: "absolute tolerance" }),
        checkField({ path: "solver.check", label: "check the events against a run at a tighter tolerance", checked: solver.check ?? true, defaultOn: true }),
        checkField({ path: "trajectories", label: "sampled trajectories in the result JSON", checked: scene.trajectories }),
      ),
    );
  }

  // [SECTION] plots
  plotsSection(plots, pelletCount) {
    const n = plots.length;
    const cards = plots.map((p, i) => this.plotCard(p, i, pelletCount, n));
    // A work–precision diagram is a figure of its own (a sweep over methods and tolerances, by its
    // own endpoint): it is offered alone, never beside other panels, where it would be refused.
    const hasWorkPrecision = plots.some((p) => p.kind === "work_precision");
    const adders = PLOT_KINDS.map((k) => {
      const alone = k.value === "work_precision" ? n > 0 : hasWorkPrecision;
      const button = addButton(k.value, `+ ${k.short}`, n >= MAX_PLOTS || alone, () =>
        this.restructure((s) => (s.plots ??= []).push(newPlot(k.value, pelletCount)), `[data-field="plots[${n}].kind"]`),
      );
      button.setAttribute("aria-label", `Add a ${KIND_TITLES[k.value]} panel`);
      if (alone) button.title = "a work–precision diagram is a figure of its own: remove the other panels first";
      return button;
    });
    return section(`Panels (${n} of ${MAX_PLOTS})`, [cards, h("div", { class: "adders" }, adders)], { field: "plots" });
  }

  plotCard(p, i, pelletCount, count) {
    const path = `plots[${i}]`;
    const kind = p.kind ?? "phase";
    const kindField = selectField({
      path: `${path}.kind`,
      label: "Kind",
      value: kind,
      options: count > 1 && kind !== "work_precision" ? PLOT_KINDS.filter((k) => k.value !== "work_precision") : PLOT_KINDS,
      onChange: (e) => this.restructure((s) => (s.plots[i] = convertPlot(s.plots[i], e.target.value)), `[data-field="${path}.kind"]`),
    });
    const pelletField = selectField({ path: `${path}.pellet`, label: "Pellet", kind: "int", value: p.pellet ?? 0, options: pelletOptions(pelletCount) });
    const title = textField({ path: `${path}.title`, label: "Title", value: p.title, placeholder: "automatic", wide: false });
    const from = numberField({ path: `${path}.t_from`, label: "from t", unit: "s", value: p.t_from, placeholder: "0" });
    const to = numberField({ path: `${path}.t_to`, label: "to t", unit: "s", value: p.t_to, placeholder: "t_end" });
    const blank = h("div", { class: "field" });

    let fields;
    if (kind === "time") {
      fields = [
        kindField, title, blank,
        pelletChecks({ path: `${path}.pellets`, legend: "Pellets drawn", count: pelletCount, selected: p.pellets ?? [], hint: "none checked: all pellets" }),
        from, to, checkField({ path: `${path}.dphi`, label: "also φ̇(t)", checked: p.dphi }),
      ];
    } else if (kind === "phase") {
      const fi = p.first_integral;
      const fiFields = [
        numberField({ path: `${path}.first_integral.phi`, label: "through φ", unit: "rad", value: fi?.phi, angle: true }),
        numberField({ path: `${path}.first_integral.dphi`, label: "through φ̇", unit: "rad/s", value: fi?.dphi }),
      ];
      // Unchecked, the point's inputs are disabled, and read() leaves disabled inputs out.
      const setFi = (on) => fiFields.forEach((f) => (f.querySelector("input").disabled = !on));
      setFi(Boolean(fi));
      fields = [
        kindField, pelletField, title,
        from, to,
        intListField({ path: `${path}.branches`, label: "Branches", value: p.branches, placeholder: "all", hint: "intervals from 1: 2, 3" }),
        checkField({ path: `${path}.friction_zone`, label: "shade the friction zone |φ| ≤ α₀ (mod 2π)", checked: p.friction_zone, wide: true }),
        h(
          "div",
          { class: "field check wide" },
          h(
            "label",
            {},
            h("input", { type: "checkbox", checked: Boolean(fi), onChange: (e) => setFi(e.target.checked) }),
            " overlay the exact first integral of the unforced motion through",
          ),
        ),
        ...fiFields,
      ];
    } else if (kind === "mechanism") {
      // The circle, limiters, pellets and forces at one instant of the run: no pellet, no window.
      fields = [
        kindField, title, blank,
        numberField({ path: `${path}.t`, label: "at t", unit: "s", value: p.t, placeholder: "0", hint: "0 … t_end" }),
      ];
    } else if (kind === "work_precision") {
      // A sweep over methods and tolerances of the whole scene: no pellet, no window.
      fields = [
        kindField, title, blank,
        h("p", { class: "note wide" }, "Error against run time for each integrator over a range of tolerances; the run is repeated for every point, so it takes longer."),
      ];
    } else {
      const cam = p.camera ?? {};
      fields = [
        kindField, pelletField, title,
        from, to, blank,
        numberField({ path: `${path}.camera.azimuth`, label: "azimuth", unit: "°", value: cam.azimuth, placeholder: "35" }),
        numberField({ path: `${path}.camera.elevation`, label: "elevation", unit: "°", value: cam.elevation, placeholder: "25", hint: "[-89, 89]" }),
        numberField({ path: `${path}.camera.distance`, label: "distance", unit: "radii", value: cam.distance, placeholder: "5", hint: "[1.5, 50]" }),
      ];
    }
    const focusAfterRemove = count > 1 ? `[data-field="plots[${Math.max(i - 1, 0)}].kind"]` : "[data-action=add-phase]";
    return card(
      path,
      `Panel ${i + 1} — ${KIND_TITLES[kind] ?? kind}`,
      removeButton(`Remove panel ${i + 1}`, false, () => this.restructure((s) => s.plots.splice(i, 1), focusAfterRemove)),
      grid(...fields),
    );
  }

  // [SECTION] image
  imageSection(scene) {
    return section(
      "Image",
      grid(
        numberField({ path: "width", label: "width", unit: "px", value: scene.width, placeholder: "1200", hint: "64–4096" }),
        numberField({ path: "height", label: "height", unit: "px", value: scene.height, placeholder: "800", hint: "64–4096" }),
      ),
    );
  }
}

// `field` lets an error about a whole list ("model.pellets") land on its section.
function section(title, content, { field } = {}) {
  return h("fieldset", { class: "section", dataset: field ? { field, kind: "group" } : undefined }, h("legend", {}, title), content, errorSlot());
}

function grid(...fields) {
  return h("div", { class: "grid" }, fields);
}

function card(path, title, removeBtn, body) {
  return h("fieldset", { class: "card", dataset: { item: path, field: path, kind: "group" } }, h("legend", {}, title), removeBtn, body, errorSlot());
}

function errorSlot() {
  return h("p", { class: "field-error", hidden: true });
}

// data-action="add-<what>" lets focus return to it after a removal.
function addButton(what, label, disabled, onClick) {
  return h("button", { type: "button", class: "add", dataset: { action: `add-${what}` }, disabled, onClick }, label);
}

function removeButton(label, disabled, onClick) {
  return h("button", { type: "button", class: "remove", "aria-label": label, title: label, disabled, onClick }, "Remove");
}

function newPlot(kind, pelletCount) {
  if (kind === "work_precision") return { kind };
  if (kind === "mechanism") return { kind, t: 0 };
  if (kind === "time") return { kind, pellets: Array.from({ length: pelletCount }, (_, i) => i) };
  return { kind, pellet: 0 };
}

// Keeps what two kinds share (window, title, pellet) when a panel changes kind; a mechanism
// shows the instant the window started at.
function convertPlot(p, kind) {
  const q = { kind };
  if (p.title !== undefined) q.title = p.title;
  if (kind === "mechanism") return { ...q, t: p.t ?? p.t_from ?? 0 };
  if (p.t_from !== undefined) q.t_from = p.t_from;
  if (p.t_to !== undefined) q.t_to = p.t_to;
  if (kind === "work_precision") return q;
  if (kind === "time") q.pellets = [p.pellet ?? p.pellets?.[0] ?? 0];
  else q.pellet = p.pellet ?? p.pellets?.[0] ?? 0;
  return q;
}

// Index lists after pellet `i` goes: drop it, shift the ones after it down.
function renumber(list, i) {
  return list.filter((j) => j !== i).map((j) => (j > i ? j - 1 : j));
}

// A new pellet where none stands (pellets must start apart), drawn by every time panel that
// drew all the pellets before it.
function addPellet(scene) {
  const pellets = scene.model.pellets;
  const taken = (a) => pellets.some((p) => typeof p.phi0 === "number" && Math.abs(wrap(a - p.phi0)) < 1e-6);
  let phi0 = 0;
  while (taken(phi0)) phi0 += 0.25;
  const n = pellets.length;
  for (const p of scene.plots ?? []) {
    // An empty or absent list means all pellets already; a list of every one is extended.
    const listsAll = Array.isArray(p.pellets) && p.pellets.length === n && Array.from({ length: n }, (_, i) => i).every((i) => p.pellets.includes(i));
    if (p.kind === "time" && listsAll) p.pellets.push(n);
  }
  pellets.push({ m: 0.2, phi0, dphi0: 0 });
}

// x wrapped to (−π, π].
function wrap(x) {
  const t = 2 * Math.PI;
  return x - t * Math.round(x / t);
}

function removePellet(scene, i) {
  scene.model.pellets.splice(i, 1);
  for (const l of scene.model.limiters ?? []) {
    if (Array.isArray(l.pellets)) l.pellets = renumber(l.pellets, i);
  }
  for (const p of scene.plots ?? []) {
    if (Array.isArray(p.pellets)) p.pellets = renumber(p.pellets, i);
    if (typeof p.pellet === "number" && p.pellet >= i) p.pellet = Math.max(p.pellet - 1, 0);
  }
}

function removeLimiter(scene, i) {
  scene.model.limiters.splice(i, 1);
  for (const l of scene.model.limiters) {
    if (l.rearm_by === i) delete l.rearm_by;
    else if (typeof l.rearm_by === "number" && l.rearm_by > i) l.rearm_by -= 1;
  }
}
