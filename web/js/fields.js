// Labelled inputs for scene fields. Every input carries `data-field`, the scene path the server
// uses in its errors ("model.pellets[1].m"), and `data-kind`, how its text becomes a JSON value;
// reading the form and placing an error next to its field both go through these two attributes.

import { h, uniqueId } from "./dom.js";
import { formatInput, parseNumber } from "./numbers.js";
import { setPath } from "./scene_path.js";

function wrap(input, labelText, { hint, unit, wide } = {}) {
  const errorId = uniqueId("err");
  const hintId = hint ? uniqueId("hint") : null;
  input.setAttribute("aria-describedby", [hintId, errorId].filter(Boolean).join(" "));
  input.dataset.errorId = errorId;
  return h(
    "div",
    { class: wide ? "field wide" : "field" },
    h("label", { for: input.id }, labelText, unit ? h("span", { class: "unit" }, ` (${unit})`) : null),
    input,
    hint ? h("small", { id: hintId, class: "hint" }, hint) : null,
    h("p", { id: errorId, class: "field-error", hidden: true }),
  );
}

// A number typed as text so that "1e-10" and "π/12" are accepted; empty means "omit the key".
export function numberField({ path, label, unit, value, angle = false, placeholder, hint, aria }) {
  const input = h("input", {
    type: "text",
    id: uniqueId("f"),
    class: "num",
    value: formatInput(value, { angle }),
    placeholder,
    spellcheck: "false",
    autocomplete: "off",
    "aria-label": aria,
    dataset: { field: path, kind: "number" },
  });
  return wrap(input, label, { hint, unit });
}

export function textField({ path, label, value, placeholder, wide = true }) {
  const input = h("input", {
    type: "text",
    id: uniqueId("f"),
    value: value ?? "",
    placeholder,
    maxlength: 200,
    dataset: { field: path, kind: "string" },
  });
  return wrap(input, label, { wide });
}

// Comma-separated whole numbers, e.g. the branches of a phase portrait.
export function intListField({ path, label, value, placeholder, hint }) {
  const input = h("input", {
    type: "text",
    id: uniqueId("f"),
    value: Array.isArray(value) ? value.join(", ") : value ?? "",
    placeholder,
    spellcheck: "false",
    dataset: { field: path, kind: "int-list" },
  });
  return wrap(input, label, { hint });
}

// options: [{value, label}]; kind "string" | "int" | "int-optional" (empty option: omit the key).
export function selectField({ path, label, options, value, kind = "string", hint, onChange, disabled }) {
  const select = h(
    "select",
    { id: uniqueId("f"), dataset: { field: path, kind }, onChange, disabled },
    options.map((o) => h("option", { value: String(o.value), selected: String(o.value) === String(value ?? "") }, o.label)),
  );
  return wrap(select, label, { hint });
}

// A boolean that is sent only when it differs from its default: when true for keys that default
// to false, when false for those that default to true (defaultOn).
export function checkField({ path, label, checked, onChange, wide = false, defaultOn = false }) {
  const errorId = uniqueId("err");
  const input = h("input", {
    type: "checkbox",
    id: uniqueId("f"),
    checked: Boolean(checked),
    "aria-describedby": errorId,
    dataset: { field: path, kind: defaultOn ? "bool-on" : "bool", errorId },
    onChange,
  });
  return h(
    "div",
    { class: wide ? "field check wide" : "field check" },
    h("label", { for: input.id }, input, " ", label),
    h("p", { id: errorId, class: "field-error", hidden: true }),
  );
}

// A list of pellet indices as one checkbox per pellet, labelled 1-based as the paper does.
export function pelletChecks({ path, legend, count, selected = [], hint }) {
  const errorId = uniqueId("err");
  const set = new Set(selected);
  return h(
    "fieldset",
    { class: "field checks wide", dataset: { field: path, kind: "index-list", errorId }, "aria-describedby": errorId },
    h("legend", {}, legend),
    Array.from({ length: count }, (_, i) =>
      h("label", { class: "inline" }, h("input", { type: "checkbox", value: String(i), checked: set.has(i) }), ` ${i + 1}`),
    ),
    hint ? h("small", { class: "hint" }, hint) : null,
    h("p", { id: errorId, class: "field-error", hidden: true }),
  );
}

export function pelletOptions(count) {
  return Array.from({ length: count }, (_, i) => ({ value: i, label: `pellet ${i + 1}` }));
}

// Reads the inputs under `root` into `into` by their data-field paths: { scene, problems:
// [{field, message}] }. Document order, so keys come out in the order a person reads them; a
// card (data-item) stands for its list element even when all its inputs are empty. A value that
// is not a number is kept as its text, so that rebuilding a form keeps what was typed; such a
// scene must not be sent.
export function readFields(root, into = {}) {
  const scene = into;
  const problems = [];
  for (const el of root.querySelectorAll("[data-field], [data-item]")) {
    const { field, kind, item } = el.dataset;
    if (item) setPath(scene, item, {});
    if (el.disabled || !field || kind === "group") continue;
    const text = el.value?.trim();
    if (kind === "bool") {
      if (el.checked) setPath(scene, field, true);
    } else if (kind === "bool-on") {
      if (!el.checked) setPath(scene, field, false);
    } else if (kind === "index-list") {
      const picked = [...el.querySelectorAll("input:checked")].map((c) => Number(c.value));
      if (picked.length) setPath(scene, field, picked);
    } else if (text === "") {
      continue; // an omitted key takes the server's documented default
    } else if (kind === "number") {
      const v = parseNumber(text);
      if (v === null) problems.push({ field, message: "is not a number (examples: 0.2, 1e-10, π/12, -pi/2)" });
      setPath(scene, field, v ?? text);
    } else if (kind === "int" || kind === "int-optional") {
      setPath(scene, field, Number(text));
    } else if (kind === "int-list") {
      const items = text.split(/[\s,;]+/).filter(Boolean);
      const values = items.map(Number);
      if (values.some((v) => !Number.isInteger(v))) {
        problems.push({ field, message: "must list whole numbers separated by commas, e.g. 2, 3" });
        setPath(scene, field, text);
      } else setPath(scene, field, values);
    } else {
      setPath(scene, field, text);
    }
  }
  return { scene, problems };
}
