// Calls to the vibro HTTP service (API.md). Every refusal becomes an ApiError carrying the
// server's message and, when it names one, the scene field at fault.

export class ApiError extends Error {
  constructor(message, { status = 0, field = null } = {}) {
    super(message);
    this.status = status;
    this.field = field;
  }
}

async function request(url, options = {}) {
  let response;
  try {
    response = await fetch(url, options);
  } catch (e) {
    if (e.name === "AbortError") throw e;
    throw new ApiError(`The server at ${location.host} did not answer (${e.message}).`);
  }
  if (response.ok) return response;
  let body = null;
  try {
    body = await response.json();
  } catch {
    // A non-JSON refusal (a proxy, a crash page): report the status alone.
  }
  const message = body?.error ?? `${response.status} ${response.statusText}`.trim();
  throw new ApiError(message, { status: response.status, field: body?.field ?? null });
}

export function postJson(url, scene, signal) {
  return request(url, {
    method: "POST",
    headers: { "Content-Type": "application/json" },
    body: JSON.stringify(scene),
    signal,
  });
}

// [{name, description}], in the server's order. Accepts a bare list or {presets: [...]}.
export async function listPresets() {
  const body = await (await request("/api/presets")).json();
  return Array.isArray(body) ? body : body.presets ?? [];
}

export async function getPreset(name) {
  return (await request(`/api/presets/${encodeURIComponent(name)}`)).json();
}

// The run result, and its text as received (offered for download unchanged).
export async function simulate(scene, signal) {
  const text = await (await postJson("/api/simulate", scene, signal)).text();
  return { result: JSON.parse(text), text };
}

// format: "png" | "svg"; resolves to {image: a Blob of that type, plotAxes: where each phase and
// φ(t) plot lies on it and what its axes span ([] when none; server/run_scene.cpp)}.
// A figure of work–precision panels only is a sweep of timed runs, which has its own endpoint.
export async function renderFigure(scene, format, signal) {
  const plots = scene.plots ?? [];
  const sweep = plots.length > 0 && plots.every((p) => p.kind === "work_precision");
  const path = sweep ? "/api/work-precision" : "/api/render";
  const response = await postJson(`${path}?format=${format}`, scene, signal);
  const header = response.headers.get("X-Vibro-Plot-Axes");
  return { image: await response.blob(), plotAxes: header ? JSON.parse(header) : [] };
}

export async function renderImage(scene, format, signal) {
  return (await renderFigure(scene, format, signal)).image;
}

// The state (pellet, φ, φ̇) under a click at (x, y) in the image's own pixels, or null outside
// every phase portrait's plot area.
export function clickedState(plotAxes, x, y) {
  for (const a of plotAxes) {
    if (a.kind !== "phase" || x < a.left || x > a.left + a.width || y < a.top || y > a.top + a.height) continue;
    return {
      pellet: a.pellet,
      phi: a.x[0] + ((x - a.left) / a.width) * (a.x[1] - a.x[0]),
      dphi: a.y[1] - ((y - a.top) / a.height) * (a.y[1] - a.y[0]),
    };
  }
  return null;
}

// Where a value pair (x, y) in a plot's axes lies on the image, in its own pixels.
export function plotPoint(a, x, y) {
  return {
    x: a.left + ((x - a.x[0]) / (a.x[1] - a.x[0])) * a.width,
    y: a.top + ((a.y[1] - y) / (a.y[1] - a.y[0])) * a.height,
  };
}
