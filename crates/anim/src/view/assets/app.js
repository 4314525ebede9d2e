// animate view: the page. It asks the server for frames (a quarter size first, then the
// whole frame), follows the manifest through a long poll (/api/wait), shows the folder's
// state and names what a click hits (and asks again after each reload). No library, no
// network beyond this server. direct.js (paths, camera key) and ab.js (the A/B wipe)
// follow it and hang on `view.hooks`: each is told of every picture shown.
"use strict";
const $ = (id) => document.getElementById(id);
const client = "p" + Math.random().toString(36).slice(2, 12);
const view = { state: null, gen: 0, cur: 0, token: 0, playing: false, log: [], shownGen: 0,
  hooks: [], shown: null };
window.view = view;

function note(kind, extra) {
  view.log.push(Object.assign({ kind, t: Date.now() }, extra));
  if (view.log.length > 2000) view.log.splice(0, 1000);
}

async function frame(n, scale, signalToken) {
  const r = await fetch(`/api/frame?n=${n}&scale=${scale}&client=${client}`);
  if (r.status === 409) return null; // superseded by a newer request of ours
  if (!r.ok) {
    const why = await r.json().catch(() => ({ error: r.statusText }));
    throw new Error(why.error);
  }
  const gen = Number(r.headers.get("X-Generation"));
  const secs = Number(r.headers.get("X-Render-Seconds"));
  const blob = await r.blob();
  if (signalToken !== view.token) return null;
  return { blob, gen, secs };
}

function put(img, got, n, scale) {
  return new Promise((resolve) => {
    const url = URL.createObjectURL(got.blob);
    const done = () => {
      URL.revokeObjectURL(img.dataset.url || "");
      img.dataset.url = url;
      img.dataset.frame = n;
      img.dataset.scale = scale;
      img.dataset.gen = got.gen;
      document.body.dataset.shown = `${got.gen}:${n}:${scale}`;
      if (scale === 1) {
        $("drawn").textContent = `frame ${n} drawn in ${(got.secs * 1000).toFixed(0)} ms`;
        document.body.dataset.drawn = `${n}:${got.secs}`;
      }
      view.shown = { blob: got.blob, gen: got.gen, n, scale };
      note("shown", { gen: got.gen, n, scale });
      for (const hook of view.hooks) hook(n, scale, got.gen);
      resolve();
    };
    const loader = new Image();
    loader.onload = () => { img.src = url; done(); };
    loader.onerror = () => resolve();
    loader.src = url;
  });
}

function setCurrent(n) {
  const s = view.state;
  if (!s || s.frames == null) return;
  n = Math.max(0, Math.min(s.frames - 1, n | 0));
  view.cur = n;
  $("slider").value = n;
  if (document.activeElement !== $("frameNo")) $("frameNo").value = n;
  $("count").textContent = `${n} / ${s.frames - 1}`;
  document.body.dataset.frame = n;
  for (const c of document.querySelectorAll(".cell.current")) c.classList.remove("current");
  const cell = $("strip").children[n];
  if (cell) cell.classList.add("current");
  return n;
}

// Shows frame n: a quarter size at once, then (unless playing) the whole frame.
async function show(n, whole = !view.playing) {
  n = setCurrent(n);
  if (n === undefined) return;
  const my = ++view.token;
  try {
    const q = await frame(n, 4, my);
    if (!q) return;
    await put($("frame"), q, n, 4);
    if (!whole || my !== view.token) return;
    const f = await frame(n, 1, my);
    if (f && my === view.token) await put($("frame"), f, n, 1);
  } catch (e) {
    note("frame-error", { message: String(e.message) });
  }
}

function applyState(s) {
  view.state = s;
  view.gen = s.generation;
  $("gen").textContent = `load ${s.generation}`;
  $("manifest").textContent = s.manifest;
  const err = $("error");
  if (s.error) {
    err.textContent = s.error;
    err.hidden = false;
  } else {
    err.hidden = true;
    err.textContent = "";
  }
  document.body.dataset.error = s.error ? "1" : "0";
  if (s.frames != null) {
    $("slider").max = s.frames - 1;
    $("frameNo").max = s.frames - 1;
    $("size").textContent = `${s.width}×${s.height} · ${s.frames} frames · ${s.fps} fps`;
  }
  note("state", { gen: s.generation, error: s.error });
}

async function follow() {
  for (;;) {
    try {
      const r = await fetch(`/api/wait?since=${view.gen}`);
      if (!r.ok) throw new Error(`wait: ${r.status}`); // busy: retry after a pause
      const s = await r.json();
      if (s.generation !== view.gen) {
        applyState(s);
        if (!s.error && !view.playing) show(view.cur);
        if (!s.error) pick(); // the marked point, in the scene as it is now
        refreshStrip();
      }
    } catch (e) {
      await new Promise((ok) => setTimeout(ok, 1000));
    }
  }
}

async function refreshStrip() {
  try {
    const r = await fetch("/api/status");
    if (!r.ok) return;
    const s = await r.json();
    const strip = $("strip");
    while (strip.children.length > s.states.length) strip.lastChild.remove();
    while (strip.children.length < s.states.length) {
      const c = document.createElement("span");
      const i = strip.children.length;
      c.onclick = () => { pause(); show(i); };
      strip.appendChild(c);
    }
    s.states.forEach((st, i) => {
      const c = strip.children[i];
      c.className = `cell s-${st}` + (i === view.cur ? " current" : "");
      c.title = `frame ${i}: ${st.replace(/-/g, " ")}`;
    });
    $("folder").textContent = `in ${s.folder}`;
  } catch (e) { /* the next refresh tries again */ }
}

function pause() {
  if (!view.playing) return;
  view.playing = false;
  $("play").textContent = "▶";
  show(view.cur, true);
}

async function play() {
  if (view.playing || !view.state || view.state.frames == null) return;
  view.playing = true;
  $("play").textContent = "❚❚";
  const start = performance.now();
  let shown = 0;
  while (view.playing) {
    const t0 = performance.now();
    const next = (view.cur + 1) % view.state.frames;
    await show(next, false);
    shown++;
    const period = 1000 / (view.state.fps || 25);
    const left = period - (performance.now() - t0);
    if (left > 0) await new Promise((ok) => setTimeout(ok, left));
    const secs = (performance.now() - start) / 1000;
    view.fps = shown / secs;
    $("fps").textContent = `${view.fps.toFixed(1)} fps`;
  }
}

// A click names what is at that pixel of the current frame; the point stays marked, and
// after a reload of the manifest it is asked again, so the line never describes a scene
// that is no longer the one shown.
function pickAt(e) {
  const s = view.state;
  if (!s || s.frames == null) return;
  const img = $("frame");
  const x = Math.min(s.width - 1, Math.floor((e.offsetX / img.clientWidth) * s.width));
  const y = Math.min(s.height - 1, Math.floor((e.offsetY / img.clientHeight) * s.height));
  view.picked = { x, y };
  pick();
}

function placeMarker() {
  const m = $("marker"), s = view.state, img = $("frame");
  if (!view.picked || !s || !s.width) { m.hidden = true; return; }
  m.style.left = `${((view.picked.x + 0.5) / s.width) * img.clientWidth}px`;
  m.style.top = `${((view.picked.y + 0.5) / s.height) * img.clientHeight}px`;
  m.hidden = false;
}

async function pick() {
  if (!view.picked) return;
  const { x, y } = view.picked;
  const n = view.cur, gen = view.gen;
  placeMarker();
  const r = await fetch(`/api/pick?n=${n}&x=${x}&y=${y}`);
  const p = await r.json();
  const f = (v) => v.map((c) => c.toFixed(3)).join(", ");
  if (!r.ok) {
    $("pickName").textContent = p.error;
    $("pickInfo").textContent = "";
  } else if (!p.hit) {
    $("pickName").textContent = "nothing";
    $("pickInfo").textContent = `frame ${n} (${x}, ${y}): the ray leaves the scene`;
  } else {
    const h = p.hit, m = h.material;
    $("pickName").textContent = h.object;
    $("pickInfo").textContent =
      `frame ${n} (${x}, ${y}) · ${h.texture.kind} ${h.texture.colors.map((c) => `(${f(c)})`).join(" ")}` +
      ` · Kd ${m.kd} Kr ${m.kr} Kt ${m.kt} Ior ${m.ior} bump ${m.bump_type} ${m.bump_value}` +
      ` · distance ${h.distance.toFixed(3)} · normal (${f(h.normal)})`;
  }
  document.body.dataset.pick = p.hit ? p.hit.object : "nothing";
  document.body.dataset.pickGen = gen;
}

function step(d) {
  pause();
  if (view.state && view.state.frames != null) {
    show((view.cur + d + view.state.frames) % view.state.frames);
  }
}

$("slider").addEventListener("input", (e) => { pause(); show(Number(e.target.value)); });
$("frameNo").addEventListener("change", (e) => { pause(); show(Number(e.target.value)); });
$("play").onclick = () => (view.playing ? pause() : play());
$("prev").onclick = () => step(-1);
$("next").onclick = () => step(1);
$("frame").addEventListener("click", pickAt);
window.addEventListener("resize", placeMarker);
document.addEventListener("keydown", (e) => {
  if (e.target === $("frameNo") || e.target.tagName === "TEXTAREA") return; // the key field
  if (e.key === "ArrowLeft") { step(-1); e.preventDefault(); }
  else if (e.key === "ArrowRight") { step(1); e.preventDefault(); }
  else if (e.key === " ") { view.playing ? pause() : play(); e.preventDefault(); }
});

// Started once every script is in (they add their hooks first).
document.addEventListener("DOMContentLoaded", async () => {
  const s = await (await fetch("/api/state")).json();
  applyState(s);
  if (s.frames != null) show(0);
  refreshStrip();
  setInterval(refreshStrip, 2000);
  follow();
});
