// Scene fields named for people: "model.pellets[0].Omega" is "Ω of pellet 1", in rad/s. The
// analysis forms (basins, two-parameter curves) offer fields by these names and label their
// ranges with these units.

// [symbol, unit, what it is], as the scene form labels them.
const PELLET = {
  phi0: ["φ₀", "rad", "angle"],
  dphi0: ["φ̇₀", "rad/s", "velocity"],
  F0: ["F₀", "N", "force"],
  Omega: ["Ω", "rad/s", "frequency"],
  psi: ["ψ", "rad", "phase"],
  c: ["c", "1/s", "damping"],
  m: ["m", "kg", "mass"],
};
const LIMITER = { k: ["k", "", "restitution"], angle: ["angle", "rad", ""] };
const MODEL = { R: ["R", "m", "radius"], alpha0: ["α₀", "rad", "friction angle"], k_c: ["k_c", "", "pellet restitution"], g: ["g", "m/s²", "gravity"] };

// [symbol, unit, what it is, whose]: "model.pellets[0].Omega" → ["Ω", "rad/s", "frequency", " of pellet 1"].
function parts(path) {
  let m = path.match(/^model\.pellets\[(\d+)\]\.(\w+)$/);
  if (m && PELLET[m[2]]) return [...PELLET[m[2]], ` of pellet ${Number(m[1]) + 1}`];
  m = path.match(/^model\.limiters\[(\d+)\]\.(\w+)$/);
  if (m && LIMITER[m[2]]) return [...LIMITER[m[2]], ` of limiter ${Number(m[1]) + 1}`];
  m = path.match(/^model\.(\w+)$/);
  if (m && MODEL[m[1]]) return [...MODEL[m[1]], ""];
  return [path, "", "", ""];
}

// The field's unit ("" when it has none).
export function unitOf(path) {
  return parts(path)[1];
}

// "Ω of pellet 1", for a sentence.
export function parameterName(path) {
  const [symbol, , , owner] = parts(path);
  return `${symbol}${owner}`;
}

// "Ω — frequency of pellet 1 (rad/s)", for a select's option and a table's heading.
export function parameterLabel(path) {
  const [symbol, unit, what, owner] = parts(path);
  return `${symbol}${what ? ` — ${what}` : ""}${owner}${unit ? ` (${unit})` : ""}`;
}

export function parameterOptions(paths) {
  return paths.map((path) => ({ value: path, label: parameterLabel(path) }));
}

// A value shown in a form: 12 significant digits, so 1.5 · 3.3 reads 4.95, not 4.949999999999999.
export function tidy(x) {
  return Number(x.toPrecision(12));
}

// Keeps the labels of a range's fields ("from", "to", made with a unit span) in the unit of the
// field chosen in `select`: "from (rad)", "to" for a field without a unit.
export function showUnitsOf(select, ...fields) {
  const show = () => {
    const unit = unitOf(select.value);
    for (const f of fields) f.querySelector("label .unit").textContent = unit ? ` (${unit})` : "";
  };
  select.addEventListener("change", show);
  show();
}
