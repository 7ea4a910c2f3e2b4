// Scene paths as the server writes them in errors: "model.pellets[1].m", "plots[0].camera.distance".

export function parsePath(path) {
  const keys = [];
  for (const part of path.split(".")) {
    const m = part.match(/^([^[\]]*)((?:\[\d+\])*)$/);
    if (!m) return null;
    if (m[1]) keys.push(m[1]);
    for (const idx of m[2].matchAll(/\[(\d+)\]/g)) keys.push(Number(idx[1]));
  }
  return keys;
}

// Sets obj at path, creating objects and arrays on the way.
export function setPath(obj, path, value) {
  const keys = parsePath(path);
  let node = obj;
  keys.forEach((key, i) => {
    if (i === keys.length - 1) {
      node[key] = value;
      return;
    }
    if (node[key] === undefined) node[key] = typeof keys[i + 1] === "number" ? [] : {};
    node = node[key];
  });
}

// "model.pellets[1].m" → "model.pellets[1]" → "model.pellets" → "model" → null.
export function parentPath(path) {
  const m = path.match(/^(.*)(\[\d+\]|\.[^.[\]]+)$/);
  return m ? m[1] : null;
}
