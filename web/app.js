// The page: a scene editor on the left, the run on the right. This file wires the modules
// together; each view and each encoding lives in web/js/.

import { ApiError, getPreset, listPresets, renderImage, simulate } from "./js/api.js";
import { curlCommand } from "./js/curl.js";
import { fill } from "./js/dom.js";
import { showEvents } from "./js/events_table.js";
import { clearFieldErrors, revealField, showFieldError } from "./js/field_errors.js";
import { readHash, sceneLink } from "./js/permalink.js";
import { describePreset, fillPicker, sameScene } from "./js/presets.js";
import { SceneForm } from "./js/scene_form.js";
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
    const [run, image] = await Promise.all([
      simulate(scene, controller.signal),
      renderImage(scene, format, controller.signal),
    ]);
    showRun(scene, run, image, format);
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

function showRun(scene, { result, text }, image, format) {
  forgetRun();
  const imageUrl = URL.createObjectURL(image);
  const jsonUrl = URL.createObjectURL(new Blob([text], { type: "application/json" }));
  state.run = { scene, images: { [format]: imageUrl }, json: jsonUrl };

  const panels = (scene.plots ?? []).map((p) => p.kind).join(", ");
  const img = new Image();
  img.src = imageUrl;
  img.alt = `Figure of the scene${scene.name ? ` “${scene.name}”` : ""}${panels ? `: ${panels} panels` : ""}. The summary below states the outcome in words.`;
  img.id = "figure";
  fill(ui.imageBox, img);

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

// About the page itself (a broken link), kept across renders until dismissed.
function showNotice(message) {
  $("notice-text").textContent = message;
  $("notice").hidden = false;
}
$("notice-dismiss").addEventListener("click", () => ($("notice").hidden = true));

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
  if (wanted.scene) {
    // A scene from a link: name the preset it came from, if the server still has it.
    const name = wanted.scene.name;
    state.preset = name && [...ui.picker.options].some((o) => o.value === name) ? await getPreset(name) : null;
    state.presetAsForm = state.preset ? asForm(state.preset) : null;
    ui.picker.value = state.preset ? name : "";
    try {
      form.load(wanted.scene);
      edited();
    } catch (e) {
      showNotice(`The link's scene could not be shown in the form (${e.message}); the paper scene is shown instead.`);
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
