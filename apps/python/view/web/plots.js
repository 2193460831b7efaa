// SPDX-License-Identifier: BSD-3-Clause
// The two 2-D plots beside the scene, drawn on canvases: the journal orbit in clearance units
// (rims A and B, the unit circle is the clearance) and the normal force against time. Each has a
// static background (the whole run, coloured by scenario) drawn once into an offscreen canvas,
// and a cursor drawn per frame, so that a 20 000-frame run plays without redrawing the curves.

import { JOINT } from "./run_data.js";

// The force axis of a run whose joint never carries a force (free flight only) [N].
const MIN_FORCE_AXIS = 1;
const TOTAL_FORCE_COLOUR = "#1f77b4";  // matplotlib's tab:blue, as the figures' |F| curve

function background(canvas) {
  const off = document.createElement("canvas");
  off.width = canvas.width;
  off.height = canvas.height;
  return off;
}

// A polyline whose segment to point k has the colour of scenario k (batched by colour runs).
function drawScenarioPath(ctx, run, xy, scenarioOf, joint) {
  let colour = null;
  ctx.lineWidth = 1;
  for (let f = 0; f < run.frameCount; ++f) {
    const [x, y] = xy(f);
    if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
    const c = run.scenarioColour(scenarioOf(f), joint);
    if (c !== colour) {
      if (colour !== null) { ctx.lineTo(x, y); ctx.stroke(); }
      ctx.strokeStyle = c;
      ctx.beginPath();
      ctx.moveTo(x, y);
      colour = c;
    } else {
      ctx.lineTo(x, y);
    }
  }
  if (colour !== null) ctx.stroke();
}

export class OrbitPlot {
  constructor(canvas, run, joint) {
    this.canvas = canvas;
    this.run = run;
    this.joint = joint;
    this.base = background(canvas);
    const o = joint.offset;
    const cr = joint.radial_clearance;
    let reach = 1.15;
    for (let f = 0; f < run.frameCount; ++f) {
      for (const rim of [JOINT.rimA, JOINT.rimB]) {
        const r = Math.hypot(run.value(f, o + rim), run.value(f, o + rim + 1)) / cr;
        if (Number.isFinite(r)) reach = Math.max(reach, 1.05 * r);
      }
    }
    this.scale = (0.5 * canvas.width) / reach;
    const ctx = this.base.getContext("2d");
    ctx.fillStyle = "#fff";
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    ctx.strokeStyle = "#999";
    ctx.beginPath();
    ctx.arc(canvas.width / 2, canvas.height / 2, this.scale, 0, 2 * Math.PI);
    ctx.stroke();
    ctx.fillStyle = "#777";
    ctx.fillText("c_r", canvas.width / 2 + this.scale * 0.72, canvas.height / 2 - this.scale * 0.72);
    const scenario = (f) => run.value(f, o + JOINT.scenario);
    for (const rim of [JOINT.rimA, JOINT.rimB]) {
      drawScenarioPath(ctx, run, (f) => this.pixel(run.value(f, o + rim), run.value(f, o + rim + 1)), scenario,
                       this.joint);
    }
  }

  pixel(u, v) {
    const cr = this.joint.radial_clearance;
    return [this.canvas.width / 2 + (u / cr) * this.scale, this.canvas.height / 2 - (v / cr) * this.scale];
  }

  draw(frame) {
    const ctx = this.canvas.getContext("2d");
    ctx.drawImage(this.base, 0, 0);
    const o = this.joint.offset;
    const colour = this.run.scenarioColour(this.run.value(frame, o + JOINT.scenario), this.joint);
    for (const [rim, filled, name] of [[JOINT.rimA, true, "A"], [JOINT.rimB, false, "B"]]) {
      const [x, y] = this.pixel(this.run.value(frame, o + rim), this.run.value(frame, o + rim + 1));
      ctx.beginPath();
      ctx.arc(x, y, 5, 0, 2 * Math.PI);
      ctx.lineWidth = 2;
      ctx.strokeStyle = "#000";
      ctx.fillStyle = colour;
      if (filled) ctx.fill();
      ctx.stroke();
      ctx.fillStyle = "#000";
      ctx.fillText(name, x + 7, y - 7);
    }
  }
}

export class ForcePlot {
  constructor(canvas, run, joint) {
    this.canvas = canvas;
    this.run = run;
    this.joint = joint;
    this.base = background(canvas);
    this.margin = { left: 44, right: 6, top: 6, bottom: 18 };
    // The axis spans the larger of the contact and the whole force (a lubricated joint's film
    // carries the load while F_N is 0); a run without any force gets 0 to MIN_FORCE_AXIS N.
    const peak = Math.max(joint.peak_force, joint.peak_total_force ?? 0);
    this.top = peak > 0 ? peak * 1.05 : MIN_FORCE_AXIS;
    const ctx = this.base.getContext("2d");
    const { left, right, top, bottom } = this.margin;
    ctx.fillStyle = "#fff";
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    ctx.strokeStyle = "#999";
    ctx.strokeRect(left, top, canvas.width - left - right, canvas.height - top - bottom);
    ctx.fillStyle = "#555";
    ctx.textAlign = "right";
    // Whole newtons from 100 N up, so that "4010" fits the margin where "4.01e+3" would not.
    ctx.fillText(this.top >= 100 ? String(Math.round(this.top)) : this.top.toPrecision(3), left - 3, top + 9);
    ctx.fillText("0", left - 3, canvas.height - bottom);
    ctx.textAlign = "left";
    ctx.fillText(`${run.manifest.start_time.toPrecision(3)} s`, left, canvas.height - 4);
    ctx.textAlign = "right";
    ctx.fillText(`${run.manifest.end_time.toPrecision(3)} s`, canvas.width - right, canvas.height - 4);
    const o = joint.offset;
    // The whole force |F| (film + contact) in blue under the contact force coloured by scenario.
    ctx.strokeStyle = TOTAL_FORCE_COLOUR;
    ctx.lineWidth = 1;
    ctx.beginPath();
    for (let f = 0; f < run.frameCount; ++f) {
      const [x, y] = this.pixel(run.time(f), run.value(f, o + JOINT.peakTotalForce));
      if (f === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
    }
    ctx.stroke();
    drawScenarioPath(ctx, run, (f) => this.pixel(run.time(f), run.value(f, o + JOINT.peakForce)),
                     (f) => run.value(f, o + JOINT.scenario), this.joint);
  }

  pixel(t, force) {
    const { left, right, top, bottom } = this.margin;
    const m = this.run.manifest;
    const span = Math.max(m.end_time - m.start_time, 1e-300);
    return [left + ((t - m.start_time) / span) * (this.canvas.width - left - right),
            this.canvas.height - bottom - (force / this.top) * (this.canvas.height - top - bottom)];
  }

  draw(frame) {
    const ctx = this.canvas.getContext("2d");
    ctx.drawImage(this.base, 0, 0);
    const [x] = this.pixel(this.run.time(frame), 0);
    ctx.strokeStyle = "#000";
    ctx.lineWidth = 1;
    ctx.beginPath();
    ctx.moveTo(x, this.margin.top);
    ctx.lineTo(x, this.canvas.height - this.margin.bottom);
    ctx.stroke();
  }
}
