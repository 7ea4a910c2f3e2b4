// Server jobs (API.md, "Sweeps"): a POST that answers 202 with the job's id, its status polled
// for progress, cancelled by DELETE, its result fetched when done. Sweeps and continued
// periodic motions run this way.

import { ApiError } from "./api.js";

// The body of a JSON answer; a refusal becomes an ApiError with the server's message and field.
export async function jsonOf(response) {
  let body = null;
  try {
    body = await response.json();
  } catch {
    // not JSON: the status alone
  }
  if (!response.ok) {
    throw new ApiError(body?.error ?? `${response.status} ${response.statusText}`, { status: response.status, field: body?.field ?? null });
  }
  return body;
}

// Starts the job (POST `url` with `body`) and polls it to its end: onProgress({done, total})
// while it runs. Resolves to the job's address ("/api/jobs/{id}") when done, or null when
// cancelled through `job.cancel()` (job: an object this fills with cancel()). A job that fails
// rejects with the server's reason and the field it names.
export async function runJob(url, body, job, onProgress) {
  const started = await jsonOf(await fetch(url, {
    method: "POST",
    headers: { "Content-Type": "application/json" },
    body: JSON.stringify(body),
  }));
  const at = `/api/jobs/${started.id}`;
  let cancelled = false;
  job.cancel = async () => {
    cancelled = true;
    await fetch(at, { method: "DELETE" });
  };
  for (;;) {
    const status = await jsonOf(await fetch(at));
    onProgress(status.progress);
    if (status.status === "done") return at;
    if (status.status === "cancelled" || cancelled) return null;
    if (status.status === "failed") {
      // The server says why (a budget, a value a run refused) and names the field it concerns.
      throw new ApiError(status.error ?? "the job failed on the server", { status: 200, field: status.field ?? null });
    }
    await new Promise((r) => setTimeout(r, 250));
  }
}

// The result of a finished job as an image (PNG): {image: Blob, response}.
export async function jobImage(at, query = "") {
  const response = await fetch(`${at}/result?format=png${query}`);
  if (!response.ok) await jsonOf(response);
  return { image: await response.blob(), response };
}

// The result of a finished job as JSON; query "&part=summary" asks a sweep's without its points
// and runs (docs/SERVER.md): its attractors and stats, whatever the number of cells.
export async function jobJson(at, query = "") {
  return jsonOf(await fetch(`${at}/result?format=json${query}`));
}
