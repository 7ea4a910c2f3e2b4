// Numbers as people type and read them. Inputs accept plain decimals and exponents ("1e-10")
// and, because the paper states its angles as fractions of π, simple expressions such as
// "π/12", "-pi/2" or "3π/2". Angles are shown that way only when the fraction reproduces
// the stored double exactly, so a value never changes by being displayed and read back.

// Parses +, -, *, /, parentheses, numbers and π (or "pi"); "3π" means 3·π.
// Returns a finite number, or null for anything else.
export function parseNumber(text) {
  const src = String(text).trim().replace(/\s+/g, "");
  if (src === "") return null;
  const tokens = src.match(/(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?|π|pi|[-+*/()]|./gi);
  let pos = 0;
  const peek = () => tokens[pos];
  const next = () => tokens[pos++];

  function primary() {
    const t = next();
    if (t === undefined) throw new Error("end");
    if (t === "(") {
      const v = sum();
      if (next() !== ")") throw new Error("paren");
      return v;
    }
    if (t === "-") return -primary();
    if (t === "+") return primary();
    if (t === "π" || t.toLowerCase() === "pi") return Math.PI;
    if (/^[\d.]/.test(t)) {
      const v = Number(t);
      if (Number.isNaN(v)) throw new Error("number");
      // Implicit product: "3π", "2(π+1)".
      const after = peek();
      if (after === "π" || (after && after.toLowerCase() === "pi") || after === "(") return v * primary();
      return v;
    }
    throw new Error("token");
  }
  function product() {
    let v = primary();
    while (peek() === "*" || peek() === "/") {
      const op = next();
      const r = primary();
      v = op === "*" ? v * r : v / r;
    }
    return v;
  }
  function sum() {
    let v = product();
    while (peek() === "+" || peek() === "-") {
      const op = next();
      const r = product();
      v = op === "+" ? v + r : v - r;
    }
    return v;
  }

  try {
    const v = sum();
    return pos === tokens.length && Number.isFinite(v) ? v : null;
  } catch {
    return null;
  }
}

const PI_DENOMINATORS = [1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 36, 48];

// The shortest "kπ/d" that parses back to exactly x, or null.
export function asPiFraction(x) {
  if (x === 0) return null;
  for (const d of PI_DENOMINATORS) {
    const k = Math.round((x * d) / Math.PI);
    if (k === 0 || Math.abs(k) > 4 * d) continue;
    const text = (k === 1 ? "" : k === -1 ? "-" : String(k)) + "π" + (d === 1 ? "" : "/" + d);
    if (parseNumber(text) === x) return text;
  }
  return null;
}

// The text an input shows for a stored value: exact (shortest round-trip decimal),
// or a π fraction for angles when that is exact too.
export function formatInput(x, { angle = false } = {}) {
  if (typeof x !== "number") return x === undefined || x === null ? "" : String(x);
  if (angle) {
    const pi = asPiFraction(x);
    if (pi) return pi;
  }
  return String(x);
}

// A value for reading in tables: `digits` significant digits, no trailing zeros.
// A state (an angle in rad, a speed in rad/s) as formatValue shows it, with round-off below
// 1e-12 shown as 0: a pellet at rest reads "0", not "1.8e-15" (the exact value stays in the
// cell's title).
export function formatState(x, digits = 6) {
  return typeof x === "number" && Math.abs(x) < 1e-12 ? "0" : formatValue(x, digits);
}

export function formatValue(x, digits = 6) {
  if (typeof x !== "number" || !Number.isFinite(x)) return String(x);
  if (x === 0) return "0";
  const a = Math.abs(x);
  if (a < 1e-4 || a >= 1e6) {
    return x.toExponential(Math.max(digits - 1, 0)).replace(/\.?0+e/, "e").replace("e+", "e");
  }
  const s = x.toPrecision(digits);
  return s.includes(".") ? s.replace(/\.?0+$/, "") : s;
}
