// SPDX-License-Identifier: BSD-3-Clause
// The run as clearjoint view serves it (apps/python/view/frames.py documents the layout): the
// manifest, and every frame as one Float32Array indexed as data[frame * stride + offset].

export async function loadRun() {
  const manifestResponse = await fetch("run/manifest.json");
  if (!manifestResponse.ok) throw new Error(`run/manifest.json: HTTP ${manifestResponse.status}`);
  const manifest = await manifestResponse.json();
  if (manifest.format !== "clearjoint-view-1") throw new Error(`unknown run format ${manifest.format}`);
  const framesResponse = await fetch("run/frames.f32");
  if (!framesResponse.ok) throw new Error(`run/frames.f32: HTTP ${framesResponse.status}`);
  const data = new Float32Array(await framesResponse.arrayBuffer());
  if (data.length !== manifest.frame_count * manifest.stride) {
    throw new Error(`run/frames.f32: ${data.length} numbers, expected ${manifest.frame_count} x ${manifest.stride}`);
  }
  return new RunData(manifest, data);
}

// Offsets inside a joint's block of a frame (frames.py: JOINT_HEAD_FLOATS, CONTACT_FLOATS).
export const JOINT = { scenario: 0, contactCount: 1, rimA: 2, rimB: 5, normalForce: 8, peakForce: 9,
                       totalForce: 10, peakTotalForce: 11, filmThickness: 12, contacts: 13 };
export const CONTACT_FLOATS = 6;

export class RunData {
  constructor(manifest, data) {
    this.manifest = manifest;
    this.data = data;
    this.stride = manifest.stride;
    this.frameCount = manifest.frame_count;
    this.colours = new Map(manifest.scenarios.map((s) => [s.code, s.colour]));
    this.labels = new Map(manifest.scenarios.map((s) => [s.code, s.label]));
    // A joint's own table of scenario codes (a pin in a hole writes PinInHoleScenario codes).
    this.jointColours = new Map();
    this.jointLabels = new Map();
    for (const j of manifest.joints ?? []) {
      if (!j.scenarios) continue;
      this.jointColours.set(j, new Map(j.scenarios.map((s) => [s.code, s.colour])));
      this.jointLabels.set(j, new Map(j.scenarios.map((s) => [s.code, s.label])));
    }
  }

  time(frame) { return this.data[frame * this.stride]; }

  value(frame, offset) { return this.data[frame * this.stride + offset]; }

  // The frame whose time is closest below t (report times are evenly spaced).
  frameAt(t) {
    const n = this.frameCount;
    if (n < 2) return 0;
    const t0 = this.time(0), t1 = this.time(n - 1);
    const k = Math.floor(((t - t0) / (t1 - t0)) * (n - 1) + 1e-6);
    return Math.min(n - 1, Math.max(0, k));
  }

  // The colour and label of a scenario code of `joint` (a manifest joint; without one, the
  // paper's table).
  scenarioColour(code, joint) {
    return (this.jointColours.get(joint) ?? this.colours).get(code) ?? "#ff00ff";
  }

  scenarioLabel(code, joint) {
    return (this.jointLabels.get(joint) ?? this.labels).get(code) ?? `scenario ${code}`;
  }
}
