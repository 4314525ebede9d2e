// animate view: A/B. "Hold A" keeps the picture shown now (its frame, its load of the
// manifest) as A; B is the live view, whatever frame is chosen or edit is saved next.
// A lies over B left of a wipe line, B shows right of it; drag the line (or the wipe
// slider) to move it. The paths overlay, being the live frame's, shows over B only.
// Uses app.js's `view`.
"use strict";
view.ab = { held: null, wipe: 50 };

function setWipe(pc) {
  pc = Math.max(0, Math.min(100, Number(pc)));
  view.ab.wipe = pc;
  $("abA").style.clipPath = `inset(0 ${100 - pc}% 0 0)`;
  // The paths are the live frame's: drawn over B only.
  $("paths").style.clipPath = view.ab.held ? `inset(0 0 0 ${pc}%)` : "";
  $("wipeLine").style.left = `${pc}%`;
  $("wipe").value = pc;
  document.body.dataset.wipe = pc;
}

function describe(s) {
  return `frame ${s.n} · load ${s.gen}${s.scale === 1 ? "" : ` · 1/${s.scale} size`}`;
}

function holdA() {
  const s = view.shown;
  if (!s) return;
  const a = $("abA");
  URL.revokeObjectURL(a.dataset.url || "");
  a.dataset.url = URL.createObjectURL(s.blob);
  a.onload = () => {
    view.ab.held = s;
    for (const id of ["abA", "wipeLine"]) $(id).hidden = false;
    $("wipe").disabled = false;
    $("dropA").disabled = false;
    $("abSaid").textContent = `A: ${describe(s)} ◀ ▶ B: ${describe(view.shown)} (live)`;
    setWipe(view.ab.wipe);
    document.body.dataset.held = `${s.gen}:${s.n}:${s.scale}`;
  };
  a.src = a.dataset.url;
}

function dropA() {
  const a = $("abA");
  view.ab.held = null;
  for (const id of ["abA", "wipeLine"]) $(id).hidden = true;
  $("wipe").disabled = true;
  $("dropA").disabled = true;
  URL.revokeObjectURL(a.dataset.url || "");
  a.removeAttribute("src");
  $("abSaid").textContent = "";
  $("paths").style.clipPath = "";
  document.body.dataset.held = "";
}

// Dragging the line: the wipe follows the pointer across the picture.
function dragWipe(e) {
  const line = $("wipeLine");
  line.setPointerCapture(e.pointerId);
  const move = (ev) => {
    const r = $("frame").getBoundingClientRect();
    setWipe(((ev.clientX - r.left) / r.width) * 100);
  };
  const end = () => {
    line.removeEventListener("pointermove", move);
    line.removeEventListener("pointerup", end);
  };
  line.addEventListener("pointermove", move);
  line.addEventListener("pointerup", end);
  e.preventDefault();
}

view.hooks.push(() => {
  if (view.ab.held) {
    $("abSaid").textContent = `A: ${describe(view.ab.held)} ◀ ▶ B: ${describe(view.shown)} (live)`;
  }
});
$("holdA").onclick = holdA;
$("dropA").onclick = dropA;
$("wipe").addEventListener("input", (e) => setWipe(e.target.value));
$("wipeLine").addEventListener("pointerdown", dragWipe);
document.addEventListener("keydown", (e) => {
  if (e.target.tagName === "INPUT" || e.target.tagName === "TEXTAREA") return;
  if (e.key === "a") holdA();
});
