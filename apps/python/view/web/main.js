// SPDX-License-Identifier: BSD-3-Clause
// The viewer page: loads the run, builds the scene and the plots, and plays the frames. Play
// advances simulated time at `speed` times wall-clock time; the slider picks a frame. A failure
// is written in the header in red, never left as a blank page.
//
// window.clearjointView is the page's state for the browser test (tests/view/...): ready, the
// load time, the frame shown, and the colours of the contacts drawn.

import { JOINT, loadRun } from "./run_data.js";
import { RunScene } from "./scene.js";
import { OrbitPlot, ForcePlot } from "./plots.js";

const started = performance.now();
const view = { ready: false, errors: [], frame: 0, loadSeconds: null };
window.clearjointView = view;

function fail(message) {
  view.errors.push(String(message));
  const status = document.getElementById("status");
  status.textContent = `error: ${message}`;
  status.className = "error";
}
window.addEventListener("error", (event) => fail(event.message));
window.addEventListener("unhandledrejection", (event) => fail(event.reason?.message ?? event.reason));

function legend(run) {
  // One list per table of scenario codes in the run (the paper's, the pin-in-hole one).
  const tables = new Map();
  for (const j of run.manifest.joints) {
    const key = j.geometry ?? "journal_bearing";
    if (!tables.has(key)) tables.set(key, { scenarios: j.scenarios ?? run.manifest.scenarios, seen: new Set() });
    for (let f = 0; f < run.frameCount; ++f) tables.get(key).seen.add(run.value(f, j.offset));
  }
  if (tables.size === 0) tables.set("journal_bearing", { scenarios: run.manifest.scenarios, seen: new Set() });
  const list = document.getElementById("legend");
  for (const [key, { scenarios, seen }] of tables) {
    if (tables.size > 1) {
      const heading = document.createElement("li");
      heading.textContent = key === "pin_in_hole" ? "pin in hole:" : "journal in bearing:";
      list.append(heading);
    }
    for (const s of scenarios) {
      const item = document.createElement("li");
      item.className = seen.has(s.code) ? "" : "absent";
      const swatch = document.createElement("span");
      swatch.className = "swatch";
      swatch.style.background = s.colour;
      item.append(swatch, document.createTextNode(s.label));
      list.append(item);
    }
  }
}

async function start() {
  const run = await loadRun();
  const m = run.manifest;
  document.getElementById("title").textContent = `clearjoint view: ${m.model_name || m.source}`;
  const scene = new RunScene(document.getElementById("scene"), run);
  const joint = m.joints[0];
  const orbit = joint ? new OrbitPlot(document.getElementById("orbit"), run, joint) : null;
  const force = joint ? new ForcePlot(document.getElementById("force"), run, joint) : null;
  if (joint) {
    document.getElementById("orbit-caption").textContent =
      `journal '${joint.name}': rims A (filled), B (ring), (u, v) / c_r`;
  } else {
    document.querySelectorAll("aside figure").forEach((f) => (f.style.display = "none"));
  }
  legend(run);

  const slider = document.getElementById("time");
  const label = document.getElementById("time-label");
  const playButton = document.getElementById("play");
  const speed = document.getElementById("speed");
  const magnify = document.getElementById("magnify");
  const contactState = document.getElementById("contact-state");
  slider.max = String(run.frameCount - 1);
  magnify.value = String(joint ? joint.magnification : 1);

  let frame = 0, playing = false, simTime = m.start_time, lastWall = null, dirty = true;
  function show(f) {
    frame = Math.min(Math.max(0, f), run.frameCount - 1);
    slider.value = String(frame);
    view.frame = frame;
    dirty = true;
  }
  function draw() {
    scene.update(frame);
    scene.render();
    const t = run.time(frame);
    label.textContent = `t = ${t.toFixed(6)} s`;
    if (joint) {
      orbit.draw(frame);
      force.draw(frame);
      const jv = scene.joints[0];
      const code = run.value(frame, joint.offset);
      contactState.textContent = `scenario: ${run.scenarioLabel(code, joint)}; contacts drawn: ${jv.shownColours.length}; ` +
        `F_N = ${run.value(frame, joint.offset + JOINT.normalForce).toPrecision(4)} N; ` +
        `|F| = ${run.value(frame, joint.offset + JOINT.totalForce).toPrecision(4)} N` +
        (joint.lubricated ? ` (film + contact); h_min = ${(1e6 * run.value(frame, joint.offset + JOINT.filmThickness)).toPrecision(3)} µm` : "") +
        `; clearance x ${jv.magnification}`;
      document.getElementById("inset-label").textContent =
        `joint '${joint.name}' in its bearing's frame, clearance x ${jv.magnification}`;
      document.getElementById("inset-label").style.bottom = `${(scene.insetSize ?? 0) + 10}px`;
      view.scenario = code;
      view.contactColours = jv.shownColours.slice();
    }
    view.time = t;
    view.drawnFrame = frame;
    dirty = false;
  }

  slider.addEventListener("input", () => { show(Number(slider.value)); simTime = run.time(frame); });
  playButton.addEventListener("click", () => {
    playing = !playing;
    playButton.textContent = playing ? "pause" : "play";
    if (playing && frame >= run.frameCount - 1) show(0);
    simTime = run.time(frame);
    lastWall = null;
  });
  document.addEventListener("keydown", (e) => { if (e.code === "Space" && e.target === document.body) { e.preventDefault(); playButton.click(); } });
  magnify.addEventListener("change", () => { magnify.value = String(scene.setMagnification(Number(magnify.value))); dirty = true; });
  document.getElementById("focus").addEventListener("click", () => { scene.focusJoint(); dirty = true; });
  scene.controls.addEventListener("change", () => { dirty = true; });
  window.addEventListener("resize", () => { dirty = true; });

  function tick(wall) {
    if (playing) {
      if (lastWall !== null) simTime += ((wall - lastWall) / 1000) * Number(speed.value);
      lastWall = wall;
      const next = run.frameAt(simTime);
      if (next >= run.frameCount - 1) { playing = false; playButton.textContent = "play"; }
      if (next !== frame) show(next);
    }
    if (dirty) draw();
    requestAnimationFrame(tick);
  }
  show(0);
  draw();
  requestAnimationFrame(tick);

  view.loadSeconds = (performance.now() - started) / 1000;
  view.setFrame = (f) => { show(f); draw(); return view.drawnFrame; };
  view.frameCount = run.frameCount;
  view.ready = true;
  document.getElementById("status").textContent =
    `${m.row_count} report times, ${run.frameCount} frames` +
    (m.decimation_step > 1 ? ` (every ${m.decimation_step}th; force plot keeps the peaks)` : "") +
    `; loaded in ${view.loadSeconds.toFixed(2)} s`;
}

start().catch((error) => fail(error.message ?? error));
