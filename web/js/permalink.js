// Permalinks. The whole scene travels in the URL fragment as UTF-8 JSON in base64url:
//   #scene=eyJtb2RlbCI6...      (the scene exactly as it is sent to the server)
//   #preset=paper               (a named scene, as the server holds it)
// The full scene, not "preset plus changes", so a link keeps meaning the same run even if a
// preset is later edited. The fragment never reaches the server, so links cost no request size.

export function encodeScene(scene) {
  const bytes = new TextEncoder().encode(JSON.stringify(scene));
  let binary = "";
  for (const b of bytes) binary += String.fromCharCode(b);
  return btoa(binary).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
}

export function decodeScene(text) {
  const b64 = text.replace(/-/g, "+").replace(/_/g, "/");
  const binary = atob(b64 + "=".repeat((4 - (b64.length % 4)) % 4));
  const bytes = Uint8Array.from(binary, (c) => c.charCodeAt(0));
  const scene = JSON.parse(new TextDecoder("utf-8", { fatal: true }).decode(bytes));
  if (typeof scene !== "object" || scene === null || Array.isArray(scene)) throw new Error("not a scene object");
  return scene;
}

export function sceneLink(scene) {
  return `${location.origin}${location.pathname}#scene=${encodeScene(scene)}`;
}

// What the fragment asks for: {scene}, {preset}, {error} or {} (nothing).
export function readHash(hash = location.hash) {
  const params = new URLSearchParams(hash.replace(/^#/, ""));
  if (params.has("scene")) {
    try {
      return { scene: decodeScene(params.get("scene")) };
    } catch {
      // atob's and JSON.parse's own words ("The string to be decoded is not correctly encoded")
      // tell a reader nothing; the likely cause does.
      return { error: "The link's scene could not be read: the link is damaged or cut short. The paper scene is shown instead." };
    }
  }
  if (params.has("preset")) return { preset: params.get("preset") };
  return {};
}
