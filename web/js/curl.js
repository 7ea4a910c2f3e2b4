// The shell command that makes the same request as the page. The scene goes in a quoted
// here-document, so no character in it (quotes in a title, say) needs escaping; compact JSON
// is one line and can never be the terminator line.

// what: "png" | "svg" | "json"
export function curlCommand(scene, what, origin = location.origin) {
  const name = (scene.name ?? "scene").replace(/[^\w.-]/g, "_");
  const url = what === "json" ? `${origin}/api/simulate` : `${origin}/api/render?format=${what}`;
  const out = what === "json" ? `${name}-result.json` : `${name}.${what}`;
  return [
    `curl -sS --fail-with-body -X POST '${url}' \\`,
    `  -H 'Content-Type: application/json' --data-binary @- -o ${out} <<'SCENE'`,
    JSON.stringify(scene),
    "SCENE",
  ].join("\n");
}
