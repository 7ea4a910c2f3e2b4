// The page: a scene editor on the left, the run on the right. This file wires the modules
// together; each view and each encoding lives in web/js/.

import { ApiError, clickedState, getPreset, listPresets, renderFigure, renderImage, simulate } from "./js/api.js";
import { curlCommand } from "./js/curl.js";
import { fill, h } from "./js/dom.js";
import { showEvents } from "./js/events_table.js";
import { clearFieldErrors, revealField, showFieldError } from "./js/field_errors.js";
import { formatValue } from "./js/numbers.js";
import { parameterLabel } from "./js/parameters.js";
import { readHash, sceneLink } from "./js/permalink.js";
import { describePreset, fillPicker, sameScene } from "./js/presets.js";
import { SceneForm } from "./js/scene_form.js";
import { setPath } from "./js/scene_path.js";
import { clickedValue, defaultSweep, runSweep, sweepablePaths } from "./js/sweep.js";
import { attractorTable, clickedStart, fillBasinsForm, readBasinsForm, runBasins } from "./js/basins.js";
import { describeCurves, fillFollowForm, readFollowForm, runFollow } from "./js/curves.js";
import { drawMarkers, drawMechanism, parseTrajectory } from "./js/animation.js";
import { describeOrbit, findOrbit, sceneOnOrbit } from "./js/orbit.js";
import { showSummary, showWarnings } from "./js/summary.js";

const $ = (id) => document.getElementById(id);

const ui = {
  form: $("scene-form"),
  fields: $("fields"),
  picker: $("preset"),
  about: $("preset-about"),
  results: $("results"),
  status: $("status"),
  generalError: $("general-error"),
  imageBox: $("image-box"),
  summary: $("summary"),
  warnings: $("warnings"),
  events: $("events"),
  curl: $("curl"),
  curlWhat: $("curl-what"),
  permalink: $("permalink"),
  downloads: { png: $("dl-png"), svg: $("dl-svg"), json: $("dl-json") },
};

const state = {
  preset: null, // the preset scene the form started from, as the server sent it
  presetAsForm: null, // the same, as the form reads it back
  run: null, // {scene, images: {png, svg} as object URLs, json: object URL}
  inFlight: null, // AbortController of the request under way
  runs: 0,
};

const form = new SceneForm(ui.fields, { onEdit: scheduleEdited });
// A form never shown: reads a preset the way the visible form would (its selects always send
// friction and method, say), so "edited" means the person changed something, not the defaults.
const probe = new SceneForm(document.createElement("div"), { onEdit() {} });

function asForm(scene) {
  probe.load(scene);
  return probe.read().scene;
}

// [SECTION] scene in the form

async function loadPreset(name) {
  const scene = await getPreset(name);
  state.preset = scene;
  state.presetAsForm = asForm(scene);
  ui.picker.value = name;
  form.load(scene);
  fillSweep(scene);
  edited();
}

// Called after any edit: is the form still the preset? And keep the links current.
let editTimer = 0;
function scheduleEdited() {
  clearTimeout(editTimer);
  editTimer = setTimeout(edited, 150);
}

function edited() {
  const { scene, problems } = form.read();
  const modified = state.presetAsForm ? !sameScene(scene, state.presetAsForm) : false;
  describePreset(ui.about, state.preset, modified);
  if (problems.length) return;
  // The address bar is the permalink too, so a bookmark or a reload keeps the scene.
  const link = sceneLink(scene);
  history.replaceState(null, "", link);
  ui.permalink.href = link;
  ui.curl.value = curlCommand(scene, ui.curlWhat.value);
  if (state.run && !sameScene(scene, state.run.scene)) setStatus("Edited since the last render: press Render to update.");
}

// [SECTION] render

async function render() {
  clearTimeout(editTimer);
  edited();
  clearFieldErrors(ui.fields);
  hideGeneralError();
  const { scene, problems } = form.read();
  if (problems.length) {
    problems.forEach((p) => showFieldError(ui.fields, p.field, p.message));
    revealField(ui.fields.querySelector(".invalid"));
    setStatus(`Not sent: ${problems.length === 1 ? "a field needs" : `${problems.length} fields need`} a valid value.`, true);
    return;
  }
  state.inFlight?.abort();
  const controller = new AbortController();
  state.inFlight = controller;
  const format = ui.form.elements.format.value;
  ui.results.dataset.state = "busy";
  ui.form.setAttribute("aria-busy", "true");
  setStatus("Simulating and drawing…");
  const started = performance.now();
  try {
    const [run, figure] = await Promise.all([
      simulate(scene, controller.signal),
      renderFigure(scene, format, controller.signal),
    ]);
    showRun(scene, run, figure, format);
    state.runs += 1;
    ui.results.dataset.run = String(state.runs);
    ui.results.dataset.state = "done";
    const ms = Math.round(performance.now() - started);
    setStatus(`Rendered ${format.toUpperCase()} in ${ms} ms.`);
  } catch (e) {
    if (e.name === "AbortError") return;
    ui.results.dataset.state = "error";
    showRequestError(e);
  } finally {
    if (state.inFlight === controller) {
      state.inFlight = null;
      ui.form.removeAttribute("aria-busy");
    }
  }
}

function showRun(scene, { result, text }, { image, plotAxes }, format) {
  forgetRun();
  const imageUrl = URL.createObjectURL(image);
  const jsonUrl = URL.createObjectURL(new Blob([text], { type: "application/json" }));
  state.run = { scene, images: { [format]: imageUrl }, json: jsonUrl, plotAxes };
  ui.imageBox.classList.toggle("clickable", plotAxes.length > 0);

  const panels = (scene.plots ?? []).map((p) => p.kind).join(", ");
  const img = new Image();
  img.src = imageUrl;
  img.alt = `Figure of the scene${scene.name ? ` “${scene.name}”` : ""}${panels ? `: ${panels} panels` : ""}. The summary below states the outcome in words.`;
  img.id = "figure";
  const marks = document.createElement("canvas");
  marks.id = "figure-marks";
  img.addEventListener("load", () => {
    marks.width = img.naturalWidth;
    marks.height = img.naturalHeight;
  });
  const stack = document.createElement("div");
  stack.className = "figure-stack";
  stack.append(img, marks);
  fill(ui.imageBox, stack);
  resetAnimation(scene);

  showSummary(ui.summary, result);
  showWarnings(ui.warnings, result.warnings);
  showEvents(ui.events, result.events ?? [], result.summary?.last_impact, result.stats?.trusted_until);

  const base = (scene.name ?? "scene").replace(/[^\w.-]/g, "_");
  setDownload(ui.downloads.png, state.run.images.png, `${base}.png`);
  setDownload(ui.downloads.svg, state.run.images.svg, `${base}.svg`);
  setDownload(ui.downloads.json, jsonUrl, `${base}-result.json`);
}

function forgetRun() {
  if (!state.run) return;
  Object.values(state.run.images).forEach((u) => URL.revokeObjectURL(u));
  URL.revokeObjectURL(state.run.json);
}

function setDownload(a, url, filename) {
  a.download = filename;
  if (url) a.href = url;
  else a.setAttribute("href", "#"); // fetched on first click, see below
}

// The format not rendered is drawn when its link is first used, for the scene last rendered.
for (const format of ["png", "svg"]) {
  const a = ui.downloads[format];
  a.addEventListener("click", async (e) => {
    if (!state.run || state.run.images[format]) return;
    e.preventDefault();
    try {
      const blob = await renderImage(state.run.scene, format);
      state.run.images[format] = URL.createObjectURL(blob);
      a.href = state.run.images[format];
      a.click();
    } catch (err) {
      showRequestError(err);
    }
  });
}

// A click on a phase portrait starts its pellet from the clicked (φ, φ̇), as pplane does.
ui.imageBox.addEventListener("click", async (e) => {
  const img = e.target.closest("img#figure");
  if (!img || !state.run?.plotAxes?.length) return;
  const rect = img.getBoundingClientRect();
  const scale = img.naturalWidth / rect.width;
  const at = clickedState(state.run.plotAxes, (e.clientX - rect.left) * scale, (e.clientY - rect.top) * scale);
  if (!at) return;
  const scene = structuredClone(state.run.scene);
  const pellet = scene.model.pellets[at.pellet];
  pellet.phi0 = Number(at.phi.toPrecision(4));
  pellet.dphi0 = Number(at.dphi.toPrecision(4));
  form.load(scene);
  edited();
  setStatus(`Pellet ${at.pellet + 1} starts at φ = ${pellet.phi0} rad, φ̇ = ${pellet.dphi0} rad/s.`);
  await render();
});

// [SECTION] animation

const animUi = { box: $("animation"), canvas: $("mechanism"), play: $("anim-play"), time: $("anim-time"), label: $("anim-label") };
const anim = { scene: null, trajectory: null, loading: null, t: 0, playing: false, frame: 0 };

function resetAnimation(scene) {
  cancelAnimationFrame(anim.frame);
  Object.assign(anim, { scene, trajectory: null, loading: null, t: 0, playing: false });
  animUi.play.textContent = "Play";
  animUi.time.max = String(scene.t_end);
  animUi.time.value = "0";
  animUi.label.textContent = "t = 0 s";
  animUi.box.hidden = false;
  loadTrajectory().then(() => showAt(0));
}

// The run's sampled trajectory, fetched once per run.
function loadTrajectory() {
  const scene = anim.scene;
  anim.loading ??= fetch("/api/simulate?format=csv&what=trajectory", {
    method: "POST",
    headers: { "Content-Type": "application/json" },
    body: JSON.stringify(scene),
  })
    .then((r) => (r.ok ? r.text() : Promise.reject(new Error(`${r.status}`))))
    .then((csv) => {
      if (anim.scene === scene) anim.trajectory = parseTrajectory(csv);
    })
    .catch(() => {
      animUi.label.textContent = "The trajectory could not be fetched.";
    });
  return anim.loading;
}

function showAt(t) {
  if (!anim.trajectory) return;
  anim.t = t;
  animUi.time.value = String(t);
  animUi.label.textContent = `t = ${t.toFixed(3)} s`;
  drawMechanism(animUi.canvas, anim.scene, anim.trajectory, t);
  const marks = $("figure-marks");
  if (marks && state.run) drawMarkers(marks, state.run.plotAxes, anim.trajectory, t);
}

// Plays the run in about ten seconds, or in real time when it is shorter.
function play() {
  const t_end = anim.scene.t_end;
  const rate = Math.max(1, t_end / 10);
  let last = performance.now();
  if (anim.t >= t_end) anim.t = 0;
  const step = (now) => {
    if (!anim.playing) return;
    const t = Math.min(t_end, anim.t + ((now - last) / 1000) * rate);
    last = now;
    showAt(t);
    if (t >= t_end) return pause();
    anim.frame = requestAnimationFrame(step);
  };
  anim.playing = true;
  animUi.play.textContent = "Pause";
  anim.frame = requestAnimationFrame(step);
}

function pause() {
  anim.playing = false;
  cancelAnimationFrame(anim.frame);
  animUi.play.textContent = "Play";
}

animUi.play.addEventListener("click", async () => {
  if (anim.playing) return pause();
  await loadTrajectory();
  if (anim.trajectory) play();
});
animUi.time.addEventListener("input", async () => {
  await loadTrajectory();
  showAt(Number(animUi.time.value));
});

// [SECTION] sweep

const sweepUi = {
  parameter: $("sweep-parameter"),
  from: $("sweep-from"),
  to: $("sweep-to"),
  count: $("sweep-count"),
  transient: $("sweep-transient"),
  record: $("sweep-record"),
  continuation: $("sweep-continuation"),
  run: $("sweep-run"),
  cancel: $("sweep-cancel"),
  progress: $("sweep-progress"),
  status: $("sweep-status"),
  box: $("sweep-box"),
  fields: $("sweep-fields"),
  job: null,
};
// The last diagram's scene, and where its parameter lies on the image (for a click on it).
const sweepState = { scene: null, axis: null, parameter: null };

// The panel's fields from a scene: its own sweep, or a first one around its forcing.
function fillSweep(scene) {
  const sweep = defaultSweep(scene);
  sweepUi.parameter.replaceChildren(...sweepablePaths(scene).map((path) => new Option(parameterLabel(path), path)));
  sweepUi.parameter.value = sweep.parameter;
  sweepUi.from.value = sweep.from;
  sweepUi.to.value = sweep.to;
  sweepUi.count.value = sweep.count;
  sweepUi.transient.value = sweep.transient ?? 50;
  sweepUi.record.value = sweep.record ?? 20;
  sweepUi.continuation.value = sweep.continuation ?? "none";
  fillBasinsForm(basinsUi.fields, scene);
  fillFollowForm(followUi.fields, scene);
  resetPanel(basinsUi, "The basins appear here.");
  resetPanel(followUi, "The curves appear here.");
}

// The sweep the panel asks for.
function readSweep() {
  return {
    parameter: sweepUi.parameter.value,
    from: Number(sweepUi.from.value),
    to: Number(sweepUi.to.value),
    count: Number(sweepUi.count.value),
    transient: Number(sweepUi.transient.value),
    record: Number(sweepUi.record.value),
    section: "stroboscopic",
    continuation: sweepUi.continuation.value,
  };
}

function startSweep() {
  return runPanelJob(sweepUi, {
    ask: (scene) => ({ body: { ...scene, sweep: readSweep() }, problems: [] }),
    run: runSweep,
    progressText: (done, total) => `${done} of ${total} runs`,
    show: (done, { sweep, ...scene }, seconds) => {
      sweepState.scene = scene;
      sweepState.axis = done.axis;
      sweepState.parameter = sweep.parameter;
      showJobImage(sweepUi, done.image, "sweep-figure", `Bifurcation diagram: the stroboscopic section against ${sweep.parameter} from ${sweep.from} to ${sweep.to}. Click to render the scene at a value.`);
      sweepUi.status.textContent = `${sweep.count} values in ${seconds.toFixed(1)} s. Click the diagram to render a value.`;
    },
  });
}

sweepUi.run.addEventListener("click", startSweep);
sweepUi.cancel.addEventListener("click", () => sweepUi.job?.cancel?.());
// A click on the diagram: the scene at that parameter value, rendered above.
sweepUi.box.addEventListener("click", async (e) => {
  const img = e.target.closest("img");
  if (!img || !sweepState.scene) return;
  const scale = img.naturalWidth / img.getBoundingClientRect().width;
  const rect = img.getBoundingClientRect();
  const value = clickedValue(sweepState.axis, (e.clientX - rect.left) * scale, (e.clientY - rect.top) * scale);
  if (value === null) return;
  const scene = structuredClone(sweepState.scene);
  setPath(scene, sweepState.parameter, Number(value.toPrecision(6)));
  form.load(scene);
  edited();
  sweepUi.status.textContent = `Rendering the scene at ${sweepState.parameter} = ${value.toPrecision(6)}.`;
  await render();
});

// [SECTION] periodic motion

const orbitUi = {
  periods: $("orbit-periods"),
  transient: $("orbit-transient"),
  find: $("orbit-find"),
  draw: $("orbit-draw"),
  status: $("orbit-status"),
  result: $("orbit-result"),
};
const orbitState = { scene: null, answer: null };

orbitUi.find.addEventListener("click", async () => {
  const { scene, problems } = form.read();
  if (problems.length) {
    orbitUi.status.textContent = "Fix the scene's fields first.";
    return;
  }
  orbitUi.find.disabled = true;
  orbitUi.draw.disabled = true;
  orbitUi.result.dataset.state = "busy";
  orbitUi.status.textContent = "Searching…";
  const started = performance.now();
  try {
    const answer = await findOrbit(scene, { periods: Number(orbitUi.periods.value), transient: Number(orbitUi.transient.value) });
    orbitState.scene = scene;
    orbitState.answer = answer;
    fill(orbitUi.result, ...describeOrbit(answer).map((line) => Object.assign(document.createElement("p"), { textContent: line })));
    orbitUi.result.dataset.state = answer.orbit.converged ? "done" : "none";
    orbitUi.draw.disabled = !answer.orbit.converged;
    orbitUi.status.textContent = `${answer.orbit.iterations} Newton iterations in ${Math.round(performance.now() - started)} ms.`;
  } catch (e) {
    orbitUi.result.dataset.state = "error";
    orbitUi.status.textContent = e instanceof ApiError && e.field ? `${e.field}: ${e.message}` : e.message;
  } finally {
    orbitUi.find.disabled = false;
  }
});

// The scene started on the motion, for one return: its portrait above is the closed orbit.
orbitUi.draw.addEventListener("click", async () => {
  if (!orbitState.answer) return;
  form.load(sceneOnOrbit(orbitState.scene, orbitState.answer));
  edited();
  await render();
});

// [SECTION] jobs from a panel: basins, two-parameter curves

// A panel's controls, by their ids: PREFIX-fields, -run, -cancel, -progress, -status, -box, -result.
function panelUi(prefix) {
  const at = (name) => $(`${prefix}-${name}`);
  return { fields: at("fields"), run: at("run"), cancel: at("cancel"), progress: at("progress"), status: at("status"), box: at("box"), result: at("result"), job: null };
}

// Puts a refusal next to the field it names, in the panel's form or else in the scene's, and
// returns the status line's text.
function placeJobError(e, panel) {
  if (!(e instanceof ApiError) || !e.field) return e.message;
  const own = showFieldError(panel.fields, e.field, e.message);
  const el = own ?? showFieldError(ui.fields, e.field, e.message);
  if (!el) return `${e.field}: ${e.message}`;
  revealField(el);
  return `Not done — ${fieldName(el)}: ${e.message} (${e.field}).`;
}

// Runs a panel's job: `ask(scene)` gives {body, problems} from the scene and the panel's form,
// `run(body, job, onProgress)` runs it (null when cancelled), `show(done, body, seconds)` shows
// what it gave; `progressText(done, total)` says how far it is.
async function runPanelJob(panel, { ask, run, show, progressText }) {
  clearFieldErrors(panel.fields);
  clearFieldErrors(ui.fields);
  const { scene, problems } = form.read();
  if (problems.length) {
    panel.status.textContent = "Fix the scene's fields first.";
    return;
  }
  const asked = ask(scene);
  if (asked.problems.length) {
    asked.problems.forEach((p) => showFieldError(panel.fields, p.field, p.message));
    panel.status.textContent = "Not sent: a field needs a valid value.";
    return;
  }
  const job = {};
  panel.job = job;
  panel.run.disabled = true;
  panel.cancel.disabled = false;
  panel.box.dataset.state = "busy";
  panel.progress.value = 0;
  panel.status.textContent = "Queued…";
  const started = performance.now();
  try {
    const done = await run(asked.body, job, ({ done, total }) => {
      if (panel.job !== job) return;
      panel.progress.max = Math.max(total, 1);
      panel.progress.value = done;
      panel.status.textContent = progressText(done, total);
    });
    // A new scene reset the panel (resetPanel): this job, of the old scene, is not shown even
    // if it finished before its cancel arrived.
    if (panel.job !== job) return;
    if (!done) {
      panel.status.textContent = "Cancelled.";
      panel.box.dataset.state = "cancelled";
      return;
    }
    show(done, asked.body, (performance.now() - started) / 1000);
    panel.box.dataset.state = "done";
  } catch (e) {
    if (panel.job !== job) return;
    panel.box.dataset.state = "error";
    panel.status.textContent = placeJobError(e, panel);
  } finally {
    if (panel.job === job) panel.job = null;
    panel.run.disabled = false;
    panel.cancel.disabled = true;
  }
}

// A panel for a new scene: its job (of the old one) cancelled, its result gone.
function resetPanel(panel, placeholder) {
  panel.job?.cancel?.();
  panel.job = null;
  fill(panel.box, h("p", { class: "muted" }, placeholder));
  fill(panel.result);
  panel.box.dataset.state = "idle";
  panel.progress.value = 0;
  panel.status.textContent = "";
}

// An image from a job, shown in its panel's box in place of the last one.
function showJobImage(panel, blob, id, alt) {
  if (panel.url) URL.revokeObjectURL(panel.url);
  panel.url = URL.createObjectURL(blob);
  fill(panel.box, Object.assign(new Image(), { src: panel.url, id, alt }));
}

const basinsUi = panelUi("basins");
// The last map's scene, sweep and plot area (for a click on it).
const basinsState = { scene: null, sweep: null, axis: null };

basinsUi.run.addEventListener("click", () =>
  runPanelJob(basinsUi, {
    ask: (scene) => {
      const { sweep, problems } = readBasinsForm(basinsUi.fields);
      return { body: { ...scene, sweep }, problems };
    },
    run: runBasins,
    progressText: (done, total) => `${done} of ${total} runs`,
    show: (done, { sweep: s, ...scene }, seconds) => {
      Object.assign(basinsState, { scene, sweep: s, axis: done.axis });
      showJobImage(basinsUi, done.image, "basins-figure", `Basins of attraction over ${s.parameter} from ${s.from} to ${s.to} and ${s.parameter2.parameter} from ${s.parameter2.from} to ${s.parameter2.to}${done.attractors ? ", each cell coloured by the attractor it settles on; the table below lists them" : ", each cell coloured by its period"}.`);
      fill(basinsUi.result, done.attractors ? attractorTable(done.attractors, done.cells) : null);
      basinsUi.status.textContent = `${done.cells} starts in ${seconds.toFixed(1)} s. Click a cell to render the scene from its start.`;
    },
  }),
);
basinsUi.cancel.addEventListener("click", () => basinsUi.job?.cancel?.());
// A click on a cell: the scene from that cell's start, rendered above.
basinsUi.box.addEventListener("click", async (e) => {
  const img = e.target.closest("img");
  if (!img || !basinsState.scene) return;
  const rect = img.getBoundingClientRect();
  const scale = img.naturalWidth / rect.width;
  const start = clickedStart(basinsState.axis, basinsState.sweep, (e.clientX - rect.left) * scale, (e.clientY - rect.top) * scale);
  if (!start) return;
  const { parameter, parameter2 } = basinsState.sweep;
  const scene = structuredClone(basinsState.scene);
  setPath(scene, parameter, start.x);
  setPath(scene, parameter2.parameter, start.y);
  form.load(scene);
  edited();
  basinsUi.status.textContent = `Rendering the scene from ${parameter} = ${formatValue(start.x)}, ${parameter2.parameter} = ${formatValue(start.y)}.`;
  await render();
});

const followUi = panelUi("follow");

followUi.run.addEventListener("click", () =>
  runPanelJob(followUi, {
    ask: (scene) => {
      const { request, problems } = readFollowForm(followUi.fields, Number(orbitUi.periods.value), Number(orbitUi.transient.value));
      return { body: { ...scene, periodic_orbit: request }, problems };
    },
    run: runFollow,
    progressText: (done, total) => `${Math.round((100 * done) / Math.max(total, 1))} % of the way`,
    show: (done, body, seconds) => {
      const c = body.periodic_orbit.continuation;
      showJobImage(followUi, done.image, "follow-figure", `Bifurcation curves: the ${c.follow.replace("_", " ")} followed in ${c.parameter2.parameter} against ${c.parameter}; the table below says where each curve runs and how it ended.`);
      fill(followUi.result, describeCurves(done.answer, body.periodic_orbit));
      followUi.status.textContent = `Followed in ${seconds.toFixed(1)} s.`;
    },
  }),
);
followUi.cancel.addEventListener("click", () => followUi.job?.cancel?.());

// [SECTION] errors and status

function showRequestError(e) {
  if (!(e instanceof ApiError)) {
    showGeneralError(`Unexpected failure: ${e.message}`);
    return;
  }
  const el = e.field ? showFieldError(ui.fields, e.field, e.message) : null;
  if (el) {
    revealField(el);
    setStatus(`Not rendered — ${fieldName(el)}: ${e.message} (${e.field}).`, true);
  } else {
    showGeneralError(e.field ? `${e.field}: ${e.message}` : e.message);
    setStatus("Not rendered.", true);
  }
}

// What a person calls the field: its accessible label ("Pellet 2 mass m (kg)") or its legend.
function fieldName(el) {
  const label = el.getAttribute("aria-label") || (el.id && document.querySelector(`label[for="${el.id}"]`)?.textContent);
  return (label || el.querySelector("legend")?.textContent || el.dataset.field).trim();
}

function showGeneralError(message) {
  ui.generalError.textContent = message;
  ui.generalError.hidden = false;
}

// About the page itself (a broken link): kept across renders until dismissed, or until a good
// scene loads (a preset picked, a working link opened).
function showNotice(message) {
  $("notice-text").textContent = message;
  $("notice").hidden = false;
}
function hideNotice() {
  $("notice").hidden = true;
}
$("notice-dismiss").addEventListener("click", hideNotice);

function hideGeneralError() {
  ui.generalError.hidden = true;
  ui.generalError.textContent = "";
}

function setStatus(text, isError = false) {
  ui.status.textContent = text;
  ui.status.classList.toggle("error", isError);
}

// [SECTION] copying

async function copyText(text, button) {
  try {
    await navigator.clipboard.writeText(text);
  } catch {
    // No clipboard API off a secure origin: copy through a selected text area instead.
    const area = Object.assign(document.createElement("textarea"), { value: text });
    document.body.append(area);
    area.select();
    document.execCommand("copy");
    area.remove();
  }
  const label = button.textContent;
  button.textContent = "Copied";
  setTimeout(() => (button.textContent = label), 1200);
}

// [SECTION] start

ui.form.addEventListener("submit", (e) => {
  e.preventDefault();
  render();
});

ui.picker.addEventListener("change", async () => {
  const name = ui.picker.value;
  if (!name) return;
  clearFieldErrors(ui.fields);
  hideGeneralError();
  try {
    await loadPreset(name);
    hideNotice();
    await render();
  } catch (e) {
    showRequestError(e);
  }
});

ui.curlWhat.addEventListener("change", edited);
$("copy-curl").addEventListener("click", (e) => copyText(ui.curl.value, e.currentTarget));
$("copy-link").addEventListener("click", (e) => copyText(ui.permalink.href, e.currentTarget));
window.addEventListener("hashchange", () => start().catch(showRequestError));

async function start() {
  const wanted = readHash();
  if (wanted.error) showNotice(wanted.error);
  else hideNotice();
  if (wanted.scene) {
    // A scene from a link: name the preset it came from, if the server still has it.
    const name = wanted.scene.name;
    state.preset = name && [...ui.picker.options].some((o) => o.value === name) ? await getPreset(name) : null;
    state.presetAsForm = state.preset ? asForm(state.preset) : null;
    ui.picker.value = state.preset ? name : "";
    try {
      form.load(wanted.scene);
      fillSweep(wanted.scene);
      edited();
    } catch (e) {
      console.warn("the link's scene does not fit the form:", e);
      showNotice("The link's scene has fields this page cannot show; the paper scene is shown instead.");
      await loadPreset("paper");
    }
  } else {
    await loadPreset(wanted.preset ?? "paper");
  }
  await render();
}

// The header names the server's version, so a screenshot says which engine made the figure.
async function showVersion() {
  try {
    const health = await (await fetch("/api/health")).json();
    $("health").textContent = `vibro ${health.version ?? ""} · ${health.status ?? "?"}`.replace("  ", " ");
  } catch {
    $("health").textContent = "service unreachable";
  }
}

async function init() {
  showVersion();
  try {
    fillPicker(ui.picker, await listPresets());
    await start();
  } catch (e) {
    showRequestError(e);
  }
}

init();
