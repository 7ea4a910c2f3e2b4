// The event list of a run as a table. Pellets and limiters are shown 1-based, as the paper
// and the summary sentence name them; impacts (limiter, collision, chatter) are numbered the way
// summary.last_impact counts them, so "after impact 27" can be found in the table.

import { fill, h } from "./dom.js";
import { formatState, formatValue } from "./numbers.js";

const IMPACT_KINDS = new Set(["limiter", "collision", "chatter"]);
const KIND_LABELS = {
  limiter: "limiter impact",
  collision: "collision",
  reversal: "reversal",
  stick: "stick",
  release: "release",
  chatter: "chatter",
};

// Fills `container` with kind filters and the table; `lastImpact` is summary.last_impact, and
// events after `trustedUntil` (stats.trusted_until) are marked as not trusted.
export function showEvents(container, events, lastImpact, trustedUntil = Infinity) {
  if (!events.length) {
    fill(container, h("p", { class: "muted" }, "No events: every pellet moved freely for the whole run."));
    return;
  }
  const table = h(
    "table",
    { class: "events" },
    h("caption", { class: "sr-only" }, "Events of the run"),
    h(
      "thead",
      {},
      h(
        "tr",
        {},
        h("th", { scope: "col", class: "n" }, "#"),
        h("th", { scope: "col", class: "n", title: "impact number: limiter impacts, collisions and chatter sequences" }, "impact"),
        h("th", { scope: "col", class: "n" }, "t (s)"),
        h("th", { scope: "col" }, "kind"),
        h("th", { scope: "col" }, "pellet"),
        h("th", { scope: "col" }, "limiter"),
        h("th", { scope: "col", class: "n" }, "φ (rad)"),
        h("th", { scope: "col", class: "n" }, "φ̇ before → after (rad/s)"),
      ),
    ),
  );
  const body = h("tbody");
  const counts = {};
  let impact = 0;
  events.forEach((e, i) => {
    counts[e.kind] = (counts[e.kind] ?? 0) + 1;
    const isImpact = IMPACT_KINDS.has(e.kind);
    if (isImpact) impact += 1;
    const last = isImpact && lastImpact && impact === lastImpact.index;
    body.append(row(e, i, isImpact ? impact : null, last, e.t > trustedUntil));
  });
  table.append(body);

  const filters = h(
    "fieldset",
    { class: "filters" },
    h("legend", {}, "Show"),
    Object.keys(KIND_LABELS)
      .filter((k) => counts[k])
      .map((k) =>
        h(
          "label",
          { class: "inline" },
          h("input", {
            type: "checkbox",
            checked: true,
            onChange: (ev) => table.classList.toggle(`hide-${k}`, !ev.target.checked),
          }),
          ` ${KIND_LABELS[k]} `,
          h("span", { class: "count" }, String(counts[k])),
        ),
      ),
  );
  fill(container, filters, h("div", { class: "scroll", tabindex: "0", role: "region", "aria-label": "Event table (scrolls)" }, table));
}

function row(e, i, impactNo, isLast, untrusted) {
  const pellets = e.pellets ?? [];
  const velocities = pellets.map((p, j) => {
    const change = `${formatState(e.dphi_before?.[j], 5)} → ${formatState(e.dphi_after?.[j], 5)}`;
    return h("div", {}, pellets.length > 1 ? h("span", { class: "who" }, `${p + 1}: `) : null, change);
  });
  let kind = KIND_LABELS[e.kind] ?? e.kind;
  if (e.kind === "chatter" && e.impacts_resolved) kind += ` (${e.impacts_resolved} impacts summed)`;
  return h(
    "tr",
    {
      class: `k-${e.kind}${isLast ? " last-impact" : ""}${untrusted ? " untrusted" : ""}`,
      title: untrusted ? "after the time the events are trusted until: it changes with the tolerance" : isLast ? "the last impact" : null,
    },
    h("td", { class: "n muted" }, String(i + 1)),
    h("td", { class: "n" }, impactNo ?? ""),
    h("td", { class: "n", title: String(e.t) }, formatValue(e.t, 7)),
    h("td", {}, h("span", { class: "dot" }), kind),
    h("td", {}, pellets.map((p) => p + 1).join(", ")),
    h("td", {}, e.limiter === undefined ? "" : String(e.limiter + 1)),
    h("td", { class: "n", title: String(e.phi) }, formatState(e.phi)),
    h("td", { class: "n" }, velocities),
  );
}
