// The summary of a run: the answer sentence, impact counts, where each pellet ends, what the
// run cost and how accurate it is (the error estimate sits next to the time and step counts,
// so that one is never read without the other), and the warnings.

import { fill, h } from "./dom.js";
import { asPiFraction, formatState, formatValue } from "./numbers.js";

const STATE_LABELS = { sliding: "sliding", stuck: "stuck", resting_at_limiter: "resting at limiter" };

export function showSummary(container, result) {
  const s = result.summary ?? {};
  const items = [
    ["limiter impacts", s.limiter_impacts],
    ["collisions", s.collisions],
    ["chatter sequences", s.chatter_sequences],
    ["last impact", s.last_impact ? `no. ${s.last_impact.index} at t = ${formatValue(s.last_impact.t)} s` : "none"],
  ];
  fill(container,
    s.answer ? h("p", { class: "answer" }, s.answer) : null,
    h(
      "dl",
      { class: "counts" },
      items.filter(([, v]) => v !== undefined).map(([k, v]) => h("div", {}, h("dt", {}, k), h("dd", {}, String(v)))),
    ),
    finalTable(s.final ?? []),
    statsLine(result.stats ?? {}),
  );
}

function finalTable(final) {
  if (!final.length) return null;
  return h(
    "table",
    { class: "final" },
    h("caption", {}, "Where the pellets end"),
    h(
      "thead",
      {},
      h(
        "tr",
        {},
        h("th", { scope: "col" }, "pellet"),
        h("th", { scope: "col" }, "state"),
        h("th", { scope: "col", class: "n" }, "φ (rad)"),
        h("th", { scope: "col", class: "n", title: "φ wrapped into (−π, π]" }, "φ wrapped"),
        h("th", { scope: "col", class: "n" }, "φ̇ (rad/s)"),
      ),
    ),
    h(
      "tbody",
      {},
      final.map((f, i) => {
        let state = STATE_LABELS[f.state] ?? f.state;
        if (f.limiter !== undefined) state += ` ${f.limiter + 1}`;
        return h(
          "tr",
          {},
          h("th", { scope: "row" }, String(i + 1)),
          h("td", {}, state),
          h("td", { class: "n", title: String(f.phi) }, angle(f.phi)),
          h("td", { class: "n", title: String(f.phi_wrapped) }, angle(f.phi_wrapped)),
          h("td", { class: "n", title: String(f.dphi) }, formatState(f.dphi)),
        );
      }),
    ),
  );
}

// A resting angle is often exactly a limiter's angle, such as 3π/2: say so.
function angle(x) {
  const pi = typeof x === "number" ? asPiFraction(x) : null;
  return pi ? `${formatValue(x)} = ${pi}` : formatState(x);
}

function statsLine(st) {
  const parts = [];
  const add = (label, value, title, cls) => {
    if (value !== undefined && value !== null) parts.push(h("span", { title, class: cls }, h("span", { class: "k" }, label), " ", value));
  };
  add("events", trustText(st), st.check === false
    ? "not checked: the error estimate comes from the energy balance and the first integral, which do not see event times"
    : `checked against ${st.check_method ?? "a run at a tighter tolerance"}, event by event`,
    st.check === false || st.trusted_until < st.t_reached ? "warn" : undefined);
  add("event times", st.event_time_error !== undefined ? `± ${formatValue(st.event_time_error, 2)} s` : undefined, "estimated largest error of the event times");
  add("error estimate", st.error_estimate !== undefined ? formatValue(st.error_estimate, 2) : undefined, "largest of: event-time error over √(R/g), final-state error (rad), energy-balance defect, first-integral residual");
  add("run time", st.wall_ms !== undefined ? `${formatValue(st.wall_ms, 3)} ms` + (st.check_wall_ms ? ` (check ${formatValue(st.check_wall_ms, 2)} ms)` : "") : undefined);
  add("steps", st.steps !== undefined ? `${st.steps}${st.rejected !== undefined ? ` (${st.rejected} rejected)` : ""}` : undefined);
  add("RHS evaluations", st.rhs_evals);
  add("method", st.method);
  add("energy defect", st.energy_defect !== undefined ? formatValue(st.energy_defect, 2) : undefined);
  add("first-integral residual", st.first_integral_residual !== undefined ? formatValue(st.first_integral_residual, 2) : undefined);
  add("tolerances", st.rtol !== undefined ? `rtol ${st.rtol}, atol ${st.atol}` : undefined);
  add("termination", st.termination);
  return h(
    "div",
    { class: "stats" },
    h("p", {}, parts),
    st.message ? h("p", { class: st.termination === "completed" ? "muted" : "warn" }, st.message) : null,
  );
}

function trustText(st) {
  if (st.check === false) return "not checked";
  if (st.trusted_until === undefined) return undefined;
  if (st.trusted_until < st.t_reached) return `trusted until t = ${formatValue(st.trusted_until)} s`;
  return "trusted to the end";
}

// Warnings are objects {code, message, ...} or plain strings; many of one code fold together.
export function showWarnings(container, warnings) {
  if (!warnings?.length) {
    fill(container);
    container.hidden = true;
    return;
  }
  container.hidden = false;
  const text = (w) => (typeof w === "string" ? w : w.message ?? JSON.stringify(w));
  const list = h("ul", {}, warnings.map((w) => h("li", {}, text(w))));
  const title = `${warnings.length} warning${warnings.length > 1 ? "s" : ""}`;
  fill(container,
    warnings.length <= 2
      ? [h("h3", {}, title), list]
      : h("details", {}, h("summary", {}, `${title}: `, text(warnings[0]), " …"), list),
  );
}
