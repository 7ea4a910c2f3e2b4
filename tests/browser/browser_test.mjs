// The web page in headless Chromium against a real `vibro serve`.
//
//   VIBRO=build/vibro WEB=web node tests/browser/browser_test.mjs
//   node tests/browser/browser_test.mjs build/vibro [web]
//
// Starts the server on a free loopback port, drives the page as a person would (pick the paper
// preset, Render, read the figure, the events and the summary; enter an invalid value and find
// the server's error next to that field; reopen the permalink), saves screenshots for people to
// look at, and ends with "browser: N passed, M failed". Exit 0 when all pass, 1 otherwise, 77
// (CTest's skip code) when Chromium is not installed. Uses Debian's Chromium; never downloads one.

import { spawn } from "node:child_process";
import { existsSync, mkdtempSync } from "node:fs";
import { createServer } from "node:net";
import { tmpdir } from "node:os";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";

const here = dirname(fileURLToPath(import.meta.url));
const vibro = resolve(process.argv[2] ?? process.env.VIBRO ?? "build/vibro");
const web = resolve(process.argv[3] ?? process.env.WEB ?? join(here, "../../web"));
const chromiumPath = process.env.CHROMIUM ?? "/usr/bin/chromium";
const shots = mkdtempSync(join(tmpdir(), "vibro-browser-"));

if (!existsSync(chromiumPath)) {
  console.log(`browser: skipped (no Chromium at ${chromiumPath}; apt-get install chromium)`);
  process.exit(77);
}
if (!existsSync(vibro)) {
  console.log(`browser: 0 passed, 1 failed (no vibro binary at ${vibro})`);
  process.exit(1);
}

// [SECTION] the server

function freePort() {
  return new Promise((ok, fail) => {
    const s = createServer();
    s.once("error", fail);
    s.listen(0, "127.0.0.1", () => {
      const { port } = s.address();
      s.close(() => ok(port));
    });
  });
}

async function startServer() {
  const port = await freePort();
  const proc = spawn(vibro, ["serve", "--host", "127.0.0.1", "--port", String(port), "--web", web], {
    stdio: ["ignore", "pipe", "pipe"],
  });
  let output = "";
  proc.stdout.on("data", (d) => (output += d));
  proc.stderr.on("data", (d) => (output += d));
  let exited = null;
  proc.on("exit", (code) => (exited = code));
  const base = `http://127.0.0.1:${port}`;
  const deadline = Date.now() + 20000;
  while (Date.now() < deadline) {
    if (exited !== null) throw new Error(`vibro serve exited with ${exited}:\n${output}`);
    try {
      const r = await fetch(`${base}/api/health`);
      if (r.ok) return { proc, base };
    } catch {
      // not listening yet
    }
    await new Promise((r) => setTimeout(r, 100));
  }
  proc.kill();
  throw new Error(`vibro serve did not answer /api/health within 20 s:\n${output}`);
}

// [SECTION] checks

const results = [];
async function check(name, fn) {
  const started = Date.now();
  try {
    await fn();
    results.push({ name, ok: true });
    console.log(`ok   ${name} (${Date.now() - started} ms)`);
  } catch (e) {
    results.push({ name, ok: false });
    console.log(`FAIL ${name}: ${e.message.split("\n")[0]}`);
  }
}

function expect(condition, message) {
  if (!condition) throw new Error(message);
}

// The page counts finished runs in #results[data-run]; wait for the count to pass `after`.
async function waitForRun(page, after) {
  await page.waitForFunction(
    (n) => {
      const r = document.getElementById("results");
      return Number(r.dataset.run ?? 0) > n && r.dataset.state === "done";
    },
    after,
    { timeout: 30000 },
  );
  return runCount(page);
}

async function runCount(page) {
  return page.evaluate(() => Number(document.getElementById("results").dataset.run ?? 0));
}

async function waitForRefusal(page) {
  await page.waitForFunction(() => document.getElementById("results").dataset.state === "error", null, { timeout: 30000 });
}

// Pixels of an image on the page, counted by drawing it on a canvas: the fraction that is not
// near-white (ink), and how many are a series blue (blue well above red).
async function pixelsOf(page, id) {
  return page.evaluate(async (imageId) => {
    const img = document.getElementById(imageId);
    await img.decode();
    const c = document.createElement("canvas");
    c.width = img.naturalWidth;
    c.height = img.naturalHeight;
    const ctx = c.getContext("2d");
    ctx.drawImage(img, 0, 0);
    const { data } = ctx.getImageData(0, 0, c.width, c.height);
    let ink = 0;
    let blue = 0;
    for (let i = 0; i < data.length; i += 4) {
      if (data[i] + data[i + 1] + data[i + 2] < 600) ink += 1;
      if (data[i + 2] - data[i] > 40) blue += 1;
    }
    return { width: img.naturalWidth, height: img.naturalHeight, ink: ink / (data.length / 4), blue };
  }, id);
}

// The error text shown for the input with data-field = path (via its aria-describedby slot).
async function errorNextTo(page, path) {
  return page.evaluate((p) => {
    const input = document.querySelector(`[data-field="${p}"]`);
    if (!input) return { found: false };
    const slot = document.getElementById(input.dataset.errorId);
    return {
      found: true,
      invalid: input.getAttribute("aria-invalid") === "true",
      text: slot && !slot.hidden ? slot.textContent : "",
      sameField: Boolean(slot && input.closest(".field") === slot.closest(".field")),
      described: (input.getAttribute("aria-describedby") ?? "").split(" ").includes(slot?.id),
    };
  }, path);
}

// [SECTION] the run

let server;
let browser;
try {
  server = await startServer();
  browser = await chromium.launch({
    executablePath: chromiumPath,
    args: ["--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking", "--disable-component-update", "--disable-sync", "--disable-quic"],
  });
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  const pageErrors = [];
  page.on("pageerror", (e) => pageErrors.push(e.message));

  await check("the page loads, lists the presets with the paper first, and opens a preset link", async () => {
    await page.goto(`${server.base}/#preset=grazing`);
    await waitForRun(page, 0);
    const names = await page.$$eval("#preset option", (os) => os.map((o) => o.value).filter(Boolean));
    expect(names[0] === "paper", `first preset is ${names[0]}, not paper`);
    expect(names.some((n) => n.startsWith("paper-fig")), "no paper figure presets listed");
    expect((await page.inputValue("#preset")) === "grazing", "the #preset=grazing link did not select grazing");
    expect((await page.locator("#preset-about .modified").count()) === 0, "an untouched preset is called edited");
  });

  await check("paper preset: Render shows the figure, the event table and the summary", async () => {
    const before = await runCount(page);
    await page.selectOption("#preset", "paper");
    const picked = await waitForRun(page, before);
    expect((await page.locator(".assumptions li").count()) > 0, "the paper's assumptions are not shown");
    expect((await page.inputValue('[data-field="model.R"]')) === "0.5", "the form does not hold the paper scene");
    await page.click("#render");
    await waitForRun(page, picked);
    const fig = await pixelsOf(page, "figure");
    expect(fig.width > 0 && fig.height > 0, "the figure has no size");
    expect(fig.ink > 0.005, `the figure is blank (${(fig.ink * 100).toFixed(2)} % ink)`);
    const rows = await page.locator("table.events tbody tr").count();
    expect(rows > 10, `the event table has ${rows} rows`);
    const answer = await page.textContent("#summary .answer");
    expect(/impact/.test(answer ?? ""), `no answer sentence in the summary: ${answer}`);
    expect((await page.locator("table.final tbody tr").count()) === 2, "final states are not listed for both pellets");
    // Beside the paper's three panels, work–precision (a figure of its own) is not offered.
    expect(await page.isDisabled('[data-action="add-work_precision"]'), "work–precision can be added beside other panels");
    const kinds = await page.locator('select[data-field="plots[0].kind"] option').allTextContents();
    expect(!kinds.some((k) => /work/.test(k)), `a panel beside others offers work–precision: ${kinds}`);
    const shown = await page.evaluate(async () => {
      const { formatState } = await import("/js/numbers.js");
      return [formatState(1.8e-15), formatState(-3e-13, 5), formatState(2.5e-9), formatState(0.0340701)];
    });
    expect(shown.join(" ") === "0 0 2.5e-9 0.0340701", `round-off is not shown as 0: ${shown}`);
    const stats = await page.textContent("#summary .stats");
    expect(/error estimate/.test(stats), "no error estimate in the summary");
    expect(/trusted to the end/.test(stats) && /event times ± /.test(stats), `no trust beside the run time: ${stats}`);
    expect((await page.getAttribute("#dl-json", "href"))?.startsWith("blob:"), "no result JSON download");
    expect((await page.inputValue("#curl")).includes("/api/render?format=png"), "no curl command");
    await page.screenshot({ path: join(shots, "paper.png") });
  });

  await check("pellet 2 mass = -1, Enter: the server's error appears next to that field", async () => {
    const field = '[data-field="model.pellets[1].m"]';
    await page.fill(field, "-1");
    await page.press(field, "Enter");
    await waitForRefusal(page);
    const e = await errorNextTo(page, "model.pellets[1].m");
    expect(e.found && e.invalid, "the field is not marked invalid");
    expect(e.text.length > 0, "no error text next to the field");
    expect(e.sameField && e.described, "the error text is not attached to the field");
    await page.screenshot({ path: join(shots, "error.png") });
  });

  await check("R = 0 after fixing the mass: the error moves to R", async () => {
    await page.fill('[data-field="model.pellets[1].m"]', "0.2");
    await page.fill('[data-field="model.R"]', "0");
    await page.click("#render");
    await waitForRefusal(page);
    const r = await errorNextTo(page, "model.R");
    expect(r.invalid && r.text.length > 0 && r.sameField, "no error next to R");
    const m = await errorNextTo(page, "model.pellets[1].m");
    expect(!m.invalid && m.text === "", "the old error on pellet 2's mass was not cleared");
  });

  await check("the permalink reopens the edited scene in a new page", async () => {
    await page.fill('[data-field="model.R"]', "0.5");
    await page.fill('[data-field="t_end"]', "5");
    const before = await runCount(page);
    await page.click("#render");
    await waitForRun(page, before);
    const link = await page.getAttribute("#permalink", "href");
    expect(link?.includes("#scene="), `the permalink is ${link}`);
    const second = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    second.on("pageerror", (e) => pageErrors.push(e.message));
    await second.goto(link);
    await waitForRun(second, 0);
    expect((await second.inputValue('[data-field="t_end"]')) === "5", "t_end was not restored");
    expect((await second.inputValue('[data-field="model.pellets[1].phi0"]')) === "-π/12", "pellet 2's φ₀ was not restored");
    expect((await second.locator("table.events tbody tr").count()) > 0, "the reopened scene did not run");
    await second.close();
  });

  await check("a broken link's notice says what is wrong in words, and goes once a preset loads", async () => {
    const third = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    third.on("pageerror", (e) => pageErrors.push(e.message));
    await third.goto(`${server.base}/#scene=@@not-base64`);
    await waitForRun(third, 0);
    const notice = await third.textContent("#notice-text");
    expect(await third.isVisible("#notice"), "no notice for a broken link");
    expect(/damaged or cut short/.test(notice) && !/decoded|token|JSON/.test(notice), `the notice reads: ${notice}`);
    const before = await runCount(third);
    await third.selectOption("#preset", "chatter");
    await waitForRun(third, before);
    expect(!(await third.isVisible("#notice")), "the notice stays after a good scene loaded");
    await third.close();
  });

  await check("a pellet added in the form starts apart from the others and the time panel draws it", async () => {
    const before = await runCount(page);
    await page.click('[data-action="add-pellet"]');
    await page.click("#render");
    await waitForRun(page, before);
    const scene = JSON.parse((await page.inputValue("#curl")).split("\n")[2]);
    expect(scene.model.pellets.length === 3, `the scene has ${scene.model.pellets.length} pellets`);
    const phis = scene.model.pellets.map((p) => p.phi0);
    expect(new Set(phis).size === 3, `the new pellet starts on another: ${phis}`);
    const time = scene.plots.find((p) => p.kind === "time");
    expect(time.pellets.includes(2), `the time panel draws pellets ${time.pellets}`);
    const fig = await pixelsOf(page, "figure");
    expect(fig.ink > 0.005, "the figure with three pellets is blank");
  });

  await check("the sweep panel runs the impact oscillator's sweep, and a click renders that value", async () => {
    const before = await runCount(page);
    await page.selectOption("#preset", "impact-oscillator");
    const picked = await waitForRun(page, before);
    expect((await page.inputValue("#sweep-parameter")) === "model.pellets[0].Omega", "the preset's sweep is not in the panel");
    await page.fill("#sweep-count", "24");
    await page.fill("#sweep-transient", "30");
    await page.fill("#sweep-record", "12");
    await page.selectOption("#sweep-continuation", "none");
    await page.click("#sweep-run");
    await page.waitForFunction(() => document.getElementById("sweep-box").dataset.state === "done", null, { timeout: 60000 });
    const progress = await page.evaluate(() => [document.getElementById("sweep-progress").value, document.getElementById("sweep-progress").max]);
    expect(progress[0] === 24 && progress[1] === 24, `progress ${progress}`);
    const { blue: ink } = await pixelsOf(page, "sweep-figure");
    expect(ink > 100, `the diagram has ${ink} points' pixels`);
    await page.screenshot({ path: join(shots, "sweep.png"), fullPage: true });
    // The middle of the image is inside the plot: Ω there is about the middle of 3 … 9 rad/s.
    const box = await page.locator("#sweep-figure").boundingBox();
    await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
    await waitForRun(page, picked);
    const omega = Number(await page.inputValue('[data-field="model.pellets[0].Omega"]'));
    expect(Math.abs(omega - 6) < 0.3, `the click set Ω = ${omega}, not about 6 rad/s`);
  });

  await check("a sweep that fails on the server shows the server's reason and field", async () => {
    // The job's status as a server reports a failed sweep (docs/SERVER.md): its error and field.
    const failed = { status: "failed", progress: { done: 12, total: 24 }, error: "took longer than its wall clock budget of 300 s", field: "sweep.count" };
    await page.route(/\/api\/jobs\/[^/]+$/, (route) =>
      route.request().method() === "GET" ? route.fulfill({ json: failed }) : route.continue());
    await page.click("#sweep-run");
    await page.waitForFunction(() => document.getElementById("sweep-box").dataset.state === "error", null, { timeout: 30000 });
    const said = await page.textContent("#sweep-status");
    await page.unroute(/\/api\/jobs\/[^/]+$/);
    expect(said.includes("sweep.count") && said.includes("wall clock budget"), `the page said: ${said}`);
  });

  await check("a click on a phase portrait starts its pellet there", async () => {
    // The scene on the page (the impact oscillator, from the sweep's click), asked for again.
    const scene = (await page.inputValue("#curl")).split("\n")[2];
    const picked = await runCount(page);
    const axes = await page.evaluate(async (body) => {
      const r = await fetch("/api/render?format=png", { method: "POST", headers: { "Content-Type": "application/json" }, body });
      return JSON.parse(r.headers.get("X-Vibro-Plot-Axes") ?? "[]").filter((a) => a.kind === "phase");
    }, scene);
    expect(axes.length === 1 && axes[0].pellet === 0, `the phase panels: ${JSON.stringify(axes)}`);
    const a = axes[0];
    // A quarter of the way across and down the plot area, in the image's own pixels.
    await page.locator("#figure").scrollIntoViewIfNeeded();
    const box = await page.locator("#figure").boundingBox();
    const natural = await page.evaluate(() => document.getElementById("figure").naturalWidth);
    const k = box.width / natural;
    await page.mouse.click(box.x + (a.left + a.width / 4) * k, box.y + (a.top + a.height / 4) * k);
    await waitForRun(page, picked);
    const phi = Number(await page.inputValue('[data-field="model.pellets[0].phi0"]'));
    const dphi = Number(await page.inputValue('[data-field="model.pellets[0].dphi0"]'));
    const wantPhi = a.x[0] + (a.x[1] - a.x[0]) / 4, wantDphi = a.y[1] - (a.y[1] - a.y[0]) / 4;
    expect(Math.abs(phi - wantPhi) < 0.01 * (a.x[1] - a.x[0]), `φ0 = ${phi}, clicked ${wantPhi}`);
    expect(Math.abs(dphi - wantDphi) < 0.01 * (a.y[1] - a.y[0]), `φ̇0 = ${dphi}, clicked ${wantDphi}`);
  });

  await check("the periodic-motion panel finds the impact oscillator's motion and draws it", async () => {
    // The preset at Ω = 5 rad/s (picked above, then set again): past the period doubling, its
    // period-1 motion is unstable, a multiplier below −1.
    const before = await runCount(page);
    await page.selectOption("#preset", "impact-oscillator");
    const picked = await waitForRun(page, before);
    await page.click("#orbit-find");
    await page.waitForFunction(() => document.getElementById("orbit-result").dataset.state !== "busy", null, { timeout: 30000 });
    const text = await page.textContent("#orbit-result");
    expect((await page.getAttribute("#orbit-result", "data-state")) === "done", `the search ended: ${text}`);
    expect(text.includes("unstable period-1 motion"), `the answer: ${text}`);
    expect(/Floquet multipliers: -1\.6/.test(text), `the multipliers: ${text}`);
    await page.click("#orbit-draw");
    await waitForRun(page, picked);
    const tEnd = Number(await page.inputValue('[data-field="t_end"]'));
    expect(Math.abs(tEnd - (2 * Math.PI) / 5) < 1e-9, `the scene runs one period: t_end = ${tEnd}`);
    const fig = await pixelsOf(page, "figure");
    expect(fig.ink > 0.002, "the orbit's figure is blank");
    await page.screenshot({ path: join(shots, "orbit.png"), fullPage: true });
  });

  await check("the animation plays the run: the mechanism and markers move, the slider sets the time", async () => {
    // The last render (the periodic motion drawn above): one period of the impact oscillator.
    await page.locator("#anim-play").scrollIntoViewIfNeeded();
    const painted = (id) => page.evaluate((canvasId) => {
      const c = document.getElementById(canvasId);
      const { data } = c.getContext("2d").getImageData(0, 0, c.width, c.height);
      let n = 0;
      for (let i = 3; i < data.length; i += 4) n += data[i] > 0 ? 1 : 0;
      return n;
    }, id);
    await page.click("#anim-play");
    await page.waitForTimeout(700);
    const t = Number(await page.inputValue("#anim-time"));
    expect(t > 0, `the slider did not move: t = ${t}`);
    expect((await painted("mechanism")) > 500, "the mechanism is not drawn");
    expect((await painted("figure-marks")) > 20, "no marker over the figure");
    // Pause, unless the one-period run has already played to its end and stopped by itself
    // (a click then would play it again).
    if ((await page.textContent("#anim-play")) === "Pause") await page.click("#anim-play");
    await page.evaluate(() => {
      const s = document.getElementById("anim-time");
      s.value = "0.5";
      s.dispatchEvent(new Event("input"));
    });
    await page.waitForFunction(() => document.getElementById("anim-label").textContent === "t = 0.500 s", null, { timeout: 5000 });
    await page.screenshot({ path: join(shots, "animation.png"), fullPage: true });
  });

  await check("the sweep tab maps the impact oscillator's basins on 12 x 12 starts and lists its attractors", async () => {
    const before = await runCount(page);
    await page.selectOption("#preset", "impact-oscillator");
    await waitForRun(page, before);
    // At Ω = 6.8 rad/s two period-1 motions coexist (docs/SWEEPS.md, "Basins of attraction").
    await page.fill('[data-field="model.pellets[0].Omega"]', "6.8");
    const form = "#basins-fields";
    expect((await page.inputValue(`${form} [data-field="sweep.parameter"]`)) === "model.pellets[0].phi0", "the x axis is not φ₀");
    expect((await page.inputValue(`${form} [data-field="sweep.parameter2.parameter"]`)) === "model.pellets[0].dphi0", "the y axis is not φ̇₀");
    const fromLabel = await page.textContent(`${form} label[for="${await page.getAttribute(`${form} [data-field="sweep.parameter2.from"]`, "id")}"]`);
    expect(fromLabel.includes("rad/s"), `the y range's label is "${fromLabel}"`);
    for (const [field, value] of [["sweep.from", "0.01"], ["sweep.to", "1.6"], ["sweep.count", "12"], ["sweep.parameter2.from", "-8"], ["sweep.parameter2.to", "8"], ["sweep.parameter2.count", "12"], ["sweep.transient", "100"], ["sweep.record", "8"]])
      await page.fill(`${form} [data-field="${field}"]`, value);
    expect(await page.isChecked(`${form} [data-field="sweep.classify"]`), "classify attractors is not checked");
    // The table needs the attractors only: the page asks the result's summary, not every point.
    const results = [];
    const onRequest = (r) => r.url().includes("/result?format=json") && results.push(r.url());
    page.on("request", onRequest);
    await page.click("#basins-run");
    await page.waitForFunction(() => ["done", "error"].includes(document.getElementById("basins-box").dataset.state), null, { timeout: 60000 });
    const said = await page.textContent("#basins-status");
    expect((await page.getAttribute("#basins-box", "data-state")) === "done", `the map ended: ${said}`);
    const progress = await page.evaluate(() => [document.getElementById("basins-progress").value, document.getElementById("basins-progress").max]);
    expect(progress[0] === 144 && progress[1] === 144, `progress ${progress}`);
    const img = await pixelsOf(page, "basins-figure");
    expect(img.ink > 0.2, `the basins image is mostly blank (${(img.ink * 100).toFixed(1)} % ink)`);
    const rows = await page.$$eval("table.attractors tbody tr", (trs) => trs.map((tr) => [...tr.children].map((c) => c.textContent)));
    const cells = rows.reduce((n, r) => n + Number(r.at(-2)), 0);
    expect(cells === 144, `the table's cells add up to ${cells}, not 144`);
    page.off("request", onRequest);
    expect(results.length === 1 && results[0].endsWith("&part=summary"), `the JSON results asked: ${results}`);
    // The slow and the fast motion of the docs, told apart by their section points (within 1e-3:
    // a run ends once within 1e-4 of its attractor, so the last digit shown may move).
    const near = (text, phi, dphi) => {
      const [p, v] = text.replace(/[()]/g, "").split(",").map(Number);
      return Math.abs(p - phi) < 1e-3 && Math.abs(v - dphi) < 1e-3;
    };
    const slow = rows.find((r) => near(r[3], 0.2688, 0.2004));
    const fast = rows.find((r) => near(r[3], 0.8405, 6.044));
    expect(slow && fast && slow[1] === "1" && fast[1] === "1" && slow[2] === "1", `the attractors: ${JSON.stringify(rows)}`);
    await page.locator("#basins-panel").scrollIntoViewIfNeeded();
    await page.screenshot({ path: join(shots, "basins.png"), fullPage: true });
    // A click on the map renders the scene from the start of the cell under it.
    const picked = await runCount(page);
    const box = await page.locator("#basins-figure").boundingBox();
    await page.mouse.click(box.x + box.width * 0.4, box.y + box.height * 0.5);
    await waitForRun(page, picked);
    const onGrid = (v, from, to) => {
      const k = ((v - from) / (to - from)) * 11;
      return Math.abs(k - Math.round(k)) < 1e-6 && k > -0.5 && k < 11.5;
    };
    const phi0 = Number(await page.inputValue('[data-field="model.pellets[0].phi0"]'));
    const dphi0 = Number(await page.inputValue('[data-field="model.pellets[0].dphi0"]'));
    expect(onGrid(phi0, 0.01, 1.6) && onGrid(dphi0, -8, 8), `the click started from φ0 = ${phi0}, φ̇0 = ${dphi0}, not a cell's start`);
    // Cells as the server draws them (render/parameter_range.cpp): count cells across the plot
    // area, each centred on its value, the second field running up.
    const under = await page.evaluate(async () => {
      const { clickedStart } = await import("/js/basins.js");
      const axis = { left: 100, top: 50, width: 120, height: 60 };
      const sweep = { from: 0, to: 11, count: 12, parameter2: { from: -1, to: 1, count: 3 } };
      return [[101, 109], [219, 51], [160, 80], [99, 80], [221, 80], [160, 111]].map(([x, y]) => clickedStart(axis, sweep, x, y));
    });
    expect(JSON.stringify(under) === JSON.stringify([{ x: 0, y: -1 }, { x: 11, y: 1 }, { x: 6, y: 0 }, null, null, null]), `cells under clicks: ${JSON.stringify(under)}`);
  });

  await check("a basin map the server refuses shows its error next to the field it names", async () => {
    const field = '#basins-fields [data-field="sweep.parameter2.count"]';
    await page.fill(field, "0");
    await page.click("#basins-run");
    await page.waitForFunction(() => document.getElementById("basins-box").dataset.state === "error", null, { timeout: 30000 });
    const e = await errorNextTo(page, "sweep.parameter2.count");
    expect(e.invalid && e.sameField && e.described, "the y axis's cells are not marked invalid");
    expect(/1 to 1000000/.test(e.text), `the error next to it reads: ${e.text}`);
    expect((await page.textContent("#basins-status")).includes("sweep.parameter2.count"), "the status does not name the field");
    await page.fill(field, "12");
    // A field the form has no input for (the section, refused for a scene without forcing): the
    // error goes under the form as a whole.
    const before = await runCount(page);
    await page.selectOption("#preset", "chatter");
    await waitForRun(page, before);
    await page.click("#basins-run");
    await page.waitForFunction(() => document.getElementById("basins-box").dataset.state === "error", null, { timeout: 30000 });
    const whole = await page.evaluate(() => {
      const root = document.getElementById("basins-fields");
      const slot = root.querySelector(":scope > .field-error");
      return { invalid: root.getAttribute("aria-invalid") === "true", text: slot.hidden ? "" : slot.textContent };
    });
    expect(whole.invalid && /forced pellet/.test(whole.text), `under the form: ${JSON.stringify(whole)}`);
    expect(/^Not done — Basin map: .*\(sweep\.section\)\.$/.test(await page.textContent("#basins-status")), "the status does not name the form and field");
  });

  await check("the periodic-motion panel follows the period doubling in k and draws the curves", async () => {
    const before = await runCount(page);
    await page.selectOption("#preset", "impact-oscillator");
    await waitForRun(page, before);
    const c = '#follow-fields [data-field="periodic_orbit.continuation';
    expect((await page.inputValue(`${c}.parameter"]`)) === "model.pellets[0].Omega", "the branch is not continued in Ω");
    await page.selectOption(`${c}.follow"]`, "period_doubling");
    await page.selectOption(`${c}.parameter2.parameter"]`, "model.limiters[0].k");
    await page.fill(`${c}.parameter2.from"]`, "0.75");
    await page.fill(`${c}.parameter2.to"]`, "0.85");
    await page.click("#follow-run");
    await page.waitForFunction(() => ["done", "error"].includes(document.getElementById("follow-box").dataset.state), null, { timeout: 60000 });
    const said = await page.textContent("#follow-status");
    expect((await page.getAttribute("#follow-box", "data-state")) === "done", `the follow ended: ${said}`);
    const img = await pixelsOf(page, "follow-figure");
    expect(img.ink > 0.005, "the curves' figure is blank");
    const text = await page.textContent("#follow-result");
    expect(/period doubling at 5\.5572/.test(text), `the branch's bifurcations: ${text}`);
    const rows = await page.$$eval("table.curves tbody tr", (trs) => trs.map((tr) => [...tr.children].map((c) => c.textContent)));
    expect(rows.length === 1 && rows[0][0] === "period doubling" && Number(rows[0][1]) > 3, `the curves: ${JSON.stringify(rows)}`);
    expect(rows[0][3] === "0.75 … 0.85" && /^5\.5/.test(rows[0][2]), `the curve's span: ${rows[0]}`);
    await page.locator("#h-follow").scrollIntoViewIfNeeded();
    await page.screenshot({ path: join(shots, "curves.png"), fullPage: true });
  });

  await check("following a curve on the paper scene names its mobile limiter next to that field", async () => {
    const before = await runCount(page);
    await page.selectOption("#preset", "paper");
    await waitForRun(page, before);
    await page.click("#follow-run");
    await page.waitForFunction(() => document.getElementById("follow-box").dataset.state === "error", null, { timeout: 30000 });
    const e = await errorNextTo(page, "model.limiters[0].mobile");
    expect(e.found && e.invalid && /fixed limiters only/.test(e.text), `next to the mobile limiter: ${JSON.stringify(e)}`);
    expect(/fixed limiters only/.test(await page.textContent("#follow-status")), "the status does not say why");
  });

  await check("a new scene clears the basins and cancels their job", async () => {
    let before = await runCount(page);
    await page.selectOption("#preset", "impact-oscillator");
    await waitForRun(page, before);
    await page.fill('#basins-fields [data-field="sweep.count"]', "60");
    await page.fill('#basins-fields [data-field="sweep.parameter2.count"]', "60");
    const cancelled = page.waitForRequest((r) => r.method() === "DELETE" && /\/api\/jobs\//.test(r.url()), { timeout: 30000 });
    await page.click("#basins-run");
    await page.waitForFunction(() => document.getElementById("basins-progress").value > 0, null, { timeout: 30000 });
    before = await runCount(page);
    await page.selectOption("#preset", "grazing");
    await waitForRun(page, before);
    await cancelled;
    await page.waitForFunction(() => !document.getElementById("basins-run").disabled, null, { timeout: 30000 });
    const shown = await page.evaluate(() => [document.getElementById("basins-box").dataset.state, document.getElementById("basins-box").textContent, document.getElementById("basins-status").textContent]);
    expect(shown[0] === "idle" && /appear here/.test(shown[1]) && shown[2] === "", `after the new scene: ${JSON.stringify(shown)}`);
  });

  await check("no script errors on the page", async () => {
    expect(pageErrors.length === 0, pageErrors.join("; "));
  });
} catch (e) {
  results.push({ name: "setup", ok: false });
  console.log(`FAIL setup: ${e.message}`);
} finally {
  await browser?.close();
  server?.proc.kill();
}

const passed = results.filter((r) => r.ok).length;
const failed = results.length - passed;
console.log(`screenshots: ${shots}`);
console.log(`browser: ${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
