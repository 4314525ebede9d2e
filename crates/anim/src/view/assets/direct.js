// animate view: the directing aids. The paths of the camera and of every tracked
// position, drawn over the picture as the server projects them with the shown frame's
// camera (/api/paths: the tracer's own camera, so a path meets the object it moves); and
// the shown frame's camera copied as a manifest key (/api/camera). Uses app.js's `view`.
"use strict";
const SVG = "http://www.w3.org/2000/svg";
const PATH_COLOURS = ["#4fd6ff", "#ff6fd8", "#7dff6f", "#ff9f43", "#b18cff", "#ff5c5c"];
view.paths = { on: false, key: "", data: null };

function svgEl(kind, attrs) {
  const e = document.createElementNS(SVG, kind);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  return e;
}

// Draws `data` (an /api/paths answer) into the overlay, in whole-frame pixel units.
function drawPaths(data) {
  const svg = $("paths");
  svg.replaceChildren();
  svg.setAttribute("viewBox", `0 0 ${data.width} ${data.height}`);
  const legend = $("pathsLegend");
  legend.replaceChildren();
  data.paths.forEach((p, i) => {
    const colour = i === 0 ? "#ffd83a" : PATH_COLOURS[(i - 1) % PATH_COLOURS.length];
    const g = svgEl("g", { "data-name": p.name, stroke: colour, fill: "none" });
    for (const seg of p.segments) {
      const points = seg.map(([x, y]) => `${x},${y}`).join(" ");
      g.appendChild(svgEl("polyline", { points, class: "path" }));
      for (const [x, y] of seg) g.appendChild(svgEl("circle", { cx: x, cy: y, r: 1.5, class: "tick", fill: colour }));
    }
    if (p.at) g.appendChild(svgEl("circle", { cx: p.at[0], cy: p.at[1], r: 4, class: "now" }));
    svg.appendChild(g);
    const name = document.createElement("span");
    name.style.color = colour;
    name.textContent = p.name + (i + 1 < data.paths.length ? " · " : "");
    legend.appendChild(name);
  });
  document.body.dataset.paths = `${data.generation}:${data.frame}`;
}

// Asks for the paths of the shown frame when the overlay is on and they changed.
async function refreshPaths(n, gen) {
  if (!view.paths.on) return;
  const key = `${gen}:${n}`;
  if (key === view.paths.key) return;
  view.paths.key = key;
  try {
    const r = await fetch(`/api/paths?n=${n}`);
    const data = await r.json();
    if (view.paths.key !== key) return; // a newer frame asked meanwhile
    if (!r.ok) { $("pathsLegend").textContent = data.error; return; }
    data.generation = gen;
    view.paths.data = data;
    drawPaths(data);
  } catch (e) {
    view.paths.key = ""; // the next frame shown tries again
  }
}

function togglePaths(on) {
  view.paths.on = on;
  $("showPaths").checked = on;
  $("paths").toggleAttribute("hidden", !on); // an SVG element has no `hidden` property
  $("pathsLegend").hidden = !on;
  view.paths.key = "";
  const img = $("frame");
  if (on && img.dataset.frame !== undefined) refreshPaths(Number(img.dataset.frame), Number(img.dataset.gen));
}

// The shown frame's camera as a manifest key: into the field (selected), and onto the
// clipboard where the browser allows it.
async function copyCamera() {
  const n = Number($("frame").dataset.frame ?? view.cur);
  const r = await fetch(`/api/camera?n=${n}`);
  const k = await r.json();
  const field = $("camKey"), said = $("camSaid");
  if (!r.ok) { said.textContent = k.error; return; }
  field.value = k.text;
  field.hidden = false;
  field.style.height = "auto";
  field.style.height = `${field.scrollHeight + 2}px`; // every line in sight
  field.focus();
  field.select();
  field.scrollTop = 0;
  let how = "field";
  try {
    await navigator.clipboard.writeText(k.text);
    how = "clipboard";
  } catch (e) {
    try { if (document.execCommand("copy")) how = "clipboard"; } catch (e2) { /* the field */ }
  }
  said.textContent = how === "clipboard"
    ? `frame ${n}'s camera copied: paste it into [camera] keys`
    : `frame ${n}'s camera: selected below, copy it (Ctrl+C)`;
  document.body.dataset.camera = `${n}:${how}`;
}

view.hooks.push((n, scale, gen) => refreshPaths(n, gen));
$("showPaths").addEventListener("change", (e) => togglePaths(e.target.checked));
$("copyCam").onclick = copyCamera;
document.addEventListener("keydown", (e) => {
  if (e.target.tagName === "INPUT" || e.target.tagName === "TEXTAREA") return;
  if (e.key === "p") togglePaths(!view.paths.on);
  else if (e.key === "c") copyCamera();
});
