// Puts an error next to the input its scene path names. The server's paths
// ("model.pellets[1].m", "plots[0].camera.distance", "model.limiters[0].pellets[1]") are the
// inputs' data-field values; a path with no input of its own falls back to the nearest
// enclosing one (the list's checkboxes, the pellet's card, the section), and a path that
// matches nothing is left to the caller's general error box.

import { parentPath } from "./scene_path.js";

// The element under root (or root itself) whose data-field is path.
function byField(root, path) {
  const selector = `[data-field="${CSS.escape(path)}"]`;
  return root.matches(selector) ? root : root.querySelector(selector);
}

// The element for `path`, or null.
export function findField(root, path) {
  for (let p = path; p; p = parentPath(p)) {
    const el = byField(root, p);
    if (el) return el;
  }
  return null;
}

// Marks the field and writes the message under it; returns the element, or null if none fits.
export function showFieldError(root, path, message) {
  const el = findField(root, path);
  if (!el) return null;
  el.setAttribute("aria-invalid", "true");
  el.classList.add("invalid");
  // A card or section has its own slot as its last child; an input has it by id.
  const slot = el.dataset.errorId ? document.getElementById(el.dataset.errorId) : el.querySelector(":scope > .field-error");
  if (slot) {
    slot.textContent = message;
    slot.hidden = false;
  }
  return el;
}

export function clearFieldErrors(root) {
  for (const el of root.querySelectorAll(".invalid")) {
    el.classList.remove("invalid");
    el.removeAttribute("aria-invalid");
  }
  for (const slot of root.querySelectorAll(".field-error")) {
    slot.textContent = "";
    slot.hidden = true;
  }
}

// Brings the field into view and gives it focus (a group: its first input). Only the form's
// own scroll box moves when it has one, so the figure beside it stays where it was.
export function revealField(el) {
  const target = el.matches("input, select, textarea") ? el : el.querySelector("input, select") ?? el;
  target.focus({ preventScroll: true });
  const box = scrollBox(target);
  if (!box) {
    target.scrollIntoView({ block: "center" });
    return;
  }
  const offset = target.getBoundingClientRect().top - box.getBoundingClientRect().top;
  box.scrollBy({ top: offset - box.clientHeight / 2 });
}

function scrollBox(el) {
  for (let p = el.parentElement; p && p !== document.body; p = p.parentElement) {
    const overflow = getComputedStyle(p).overflowY;
    if ((overflow === "auto" || overflow === "scroll") && p.scrollHeight > p.clientHeight) return p;
  }
  return null;
}
