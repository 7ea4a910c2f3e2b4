// The preset picker: the paper scene first, then the paper's figures, then the hard cases,
// each group in the server's order. The chosen preset's description and assumptions are shown
// because the paper leaves values open and the outcome depends on what is assumed for them.

import { fill, h } from "./dom.js";

export function groupPresets(presets) {
  const paper = presets.filter((p) => p.name === "paper");
  const figures = presets.filter((p) => p.name !== "paper" && p.name.startsWith("paper"));
  const others = presets.filter((p) => !p.name.startsWith("paper"));
  return [
    { label: "The paper", presets: paper },
    { label: "The paper's figures", presets: figures },
    { label: "Hard cases", presets: others },
  ].filter((g) => g.presets.length);
}

export function fillPicker(select, presets) {
  fill(select,
    h("option", { value: "" }, "— your own scene —"),
    groupPresets(presets).map((g) =>
      h("optgroup", { label: g.label }, g.presets.map((p) => h("option", { value: p.name, title: p.description }, p.name))),
    ),
  );
}

// scene: the preset as the server returned it; modified: the form no longer matches it.
export function describePreset(container, scene, modified) {
  if (!scene) {
    fill(container, h("p", { class: "muted" }, "A scene of your own (from a link or edited)."));
    return;
  }
  const assumptions = scene.assumptions ?? [];
  fill(container,
    modified ? h("p", { class: "modified" }, `Edited: differs from the preset “${scene.name}”.`) : null,
    scene.description ? h("p", {}, scene.description) : null,
    assumptions.length
      ? h("div", { class: "assumptions" }, h("h3", {}, "Assumptions"), h("ul", {}, assumptions.map((a) => h("li", {}, a))))
      : null,
  );
}

// Whether two scenes read from forms are the same (key order aside).
export function sameScene(a, b) {
  return canonical(a) === canonical(b);
}

function canonical(v) {
  if (Array.isArray(v)) return `[${v.map(canonical).join(",")}]`;
  if (v && typeof v === "object") {
    return `{${Object.keys(v)
      .sort()
      .map((k) => `${JSON.stringify(k)}:${canonical(v[k])}`)
      .join(",")}}`;
  }
  return JSON.stringify(v);
}
