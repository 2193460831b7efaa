// SPDX-License-Identifier: BSD-3-Clause
// The 3-D scene of a run: each recorded body as the uniform box with its mass and inertia
// (frames.py: inertia_box), ideal-joint attachment points as small spheres, and each clearance
// joint as its bearing (translucent, drawn at its true size) with the journal inside it drawn
// with the clearance magnified: the journal's offset and tilt in the bearing frame are multiplied
// by the factor, its radius and length shrunk so that the gaps are the factor times c_r and c_a
// (paper eqs. 1-2). Contacts are spheres at C_i with an arrow along the force on the journal
// (minus the normal, which points out of the bearing), in the colour of the frame's scenario.

import * as THREE from "three";
import { OrbitControls } from "three";
import { JOINT, CONTACT_FLOATS } from "./run_data.js";

const BODY_COLOURS = ["#6b8fb3", "#b39b6b", "#7fae7f", "#a77fae", "#ae7f7f", "#7faeae"];
const Y = new THREE.Vector3(0, 1, 0);
const INSET_BACKGROUND = new THREE.Color("#e3e8ee");

// A factor of at least 1 that keeps the shown journal's radius and length positive
// (max_magnification, from frames.py).
function clampMagnification(joint, factor) {
  return Math.min(Math.max(1, factor), joint.max_magnification);
}

class JointView {
  constructor(joint, parent) {
    this.joint = joint;
    this.frame = new THREE.Group();  // the bearing frame (u, v, a) at P_i
    const [u, v, a] = joint.bearing_frame.map((r) => new THREE.Vector3(...r));
    this.frame.quaternion.setFromRotationMatrix(new THREE.Matrix4().makeBasis(u, v, a));
    this.frame.position.set(...joint.bearing_point);
    parent.add(this.frame);

    const Ri = joint.bearing_radius, Li = joint.bearing_length;
    const bearing = new THREE.Mesh(
      new THREE.CylinderGeometry(Ri, Ri, Li, 64, 1, true),
      new THREE.MeshStandardMaterial({ color: "#8899aa", transparent: true, opacity: 0.35,
                                       side: THREE.DoubleSide, depthWrite: false }));
    bearing.rotation.x = Math.PI / 2;  // cylinder axis Y -> bearing axis a (local z)
    this.frame.add(bearing);
    for (const side of [-1, 1]) {  // the bases' rims, so the bearing reads as a ring
      const ring = new THREE.LineLoop(
        new THREE.BufferGeometry().setFromPoints(
          Array.from({ length: 64 }, (_, k) => new THREE.Vector3(Ri * Math.cos(k * Math.PI / 32),
                                                                  Ri * Math.sin(k * Math.PI / 32), side * Li / 2))),
        new THREE.LineBasicMaterial({ color: "#334455" }));
      this.frame.add(ring);
    }

    this.journal = new THREE.Mesh(new THREE.CylinderGeometry(1, 1, 1, 48),
                                  new THREE.MeshStandardMaterial({ color: "#c9a227", metalness: 0.3, roughness: 0.5 }));
    this.frame.add(this.journal);
    // Base A's end of the journal, marked so that rims A and B can be told apart.
    this.rimA = new THREE.Mesh(new THREE.SphereGeometry(0.12 * Ri, 16, 12),
                               new THREE.MeshStandardMaterial({ color: "#333333" }));
    this.frame.add(this.rimA);

    this.contacts = [];
    for (let k = 0; k < 6; ++k) {
      const material = new THREE.MeshBasicMaterial({ color: "#ffffff" });
      const dot = new THREE.Mesh(new THREE.SphereGeometry(0.1 * Ri, 16, 12), material);
      const arrow = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 0.6 * Ri,
                                          0xffffff, 0.2 * Ri, 0.12 * Ri);
      dot.visible = arrow.visible = false;
      this.frame.add(dot, arrow);
      this.contacts.push({ dot, arrow });
    }
    this.setMagnification(joint.magnification);
  }

  setMagnification(factor) {
    const j = this.joint;
    this.magnification = clampMagnification(j, factor);
    this.shownRadius = j.bearing_radius - this.magnification * j.radial_clearance;
    this.shownLength = j.bearing_length - 2 * this.magnification * j.axial_clearance;
    this.journal.scale.set(this.shownRadius, this.shownLength, this.shownRadius);
    return this.magnification;
  }

  update(run, frame) {
    const o = this.joint.offset, m = this.magnification;
    const rimA = new THREE.Vector3(run.value(frame, o + JOINT.rimA), run.value(frame, o + JOINT.rimA + 1),
                                   run.value(frame, o + JOINT.rimA + 2));
    const rimB = new THREE.Vector3(run.value(frame, o + JOINT.rimB), run.value(frame, o + JOINT.rimB + 1),
                                   run.value(frame, o + JOINT.rimB + 2));
    const centre = rimA.clone().add(rimB).multiplyScalar(0.5 * m);
    const d = rimA.clone().sub(rimB);  // from B to A, along +a
    const shown = new THREE.Vector3(m * d.x, m * d.y, d.z).normalize();
    this.journal.position.copy(centre);
    this.journal.quaternion.setFromUnitVectors(Y, shown);
    this.rimA.position.copy(centre).addScaledVector(shown, 0.5 * this.shownLength);

    const scenario = run.value(frame, o + JOINT.scenario);
    const colour = new THREE.Color(run.scenarioColour(scenario, this.joint));
    this.shownColours = [];
    for (let k = 0; k < this.contacts.length; ++k) {
      const base = o + JOINT.contacts + k * CONTACT_FLOATS;
      const p = new THREE.Vector3(run.value(frame, base), run.value(frame, base + 1), run.value(frame, base + 2));
      const n = new THREE.Vector3(run.value(frame, base + 3), run.value(frame, base + 4), run.value(frame, base + 5));
      const { dot, arrow } = this.contacts[k];
      const present = Number.isFinite(p.x) && Number.isFinite(n.x);
      dot.visible = arrow.visible = present;
      if (!present) continue;
      dot.position.copy(p);
      dot.material.color.copy(colour);
      arrow.position.copy(p);
      arrow.setDirection(n.clone().negate());  // the force on the journal points into the bearing
      arrow.setColor(colour);
      this.shownColours.push("#" + colour.getHexString());
    }
  }
}

export class RunScene {
  constructor(canvas, run) {
    this.run = run;
    this.canvas = canvas;
    // preserveDrawingBuffer: the browser test reads the canvas back after a frame is drawn.
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio);
    this.renderer.setScissorTest(true);
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color("#f4f6f8");
    const m = run.manifest;
    const g = new THREE.Vector3(...m.gravity);
    this.up = g.lengthSq() > 0 ? g.clone().negate().normalize() : new THREE.Vector3(0, 0, 1);
    this.scene.add(new THREE.HemisphereLight("#ffffff", "#667788", 2.0));
    const sun = new THREE.DirectionalLight("#ffffff", 1.5);
    sun.position.copy(this.up).multiplyScalar(2).add(new THREE.Vector3(1, 1, 0));
    this.scene.add(sun);

    this.bodies = new Map([["ground", this.scene]]);
    m.bodies.forEach((b, k) => {
      const group = new THREE.Group();
      const box = new THREE.Mesh(new THREE.BoxGeometry(...b.box),
                                 new THREE.MeshStandardMaterial({ color: BODY_COLOURS[k % BODY_COLOURS.length],
                                                                  transparent: true, opacity: 0.45, depthWrite: false }));
      group.add(box);
      group.userData = b;
      this.scene.add(group);
      this.bodies.set(b.name, group);
    });
    const size = this.extent();
    for (const p of m.joint_points) {
      const parent = this.bodies.get(p.body);
      if (!parent) continue;
      const dot = new THREE.Mesh(new THREE.SphereGeometry(0.015 * size, 12, 8),
                                 new THREE.MeshStandardMaterial({ color: "#555555" }));
      dot.position.set(...p.point);
      parent.add(dot);
    }
    this.joints = m.joints.map((j) => new JointView(j, this.bodies.get(j.bearing_body) ?? this.scene));

    this.camera = new THREE.PerspectiveCamera(40, 1, size * 1e-3, size * 100);
    this.camera.up.copy(this.up);
    this.controls = new OrbitControls(this.camera, canvas);
    this.inset = new THREE.PerspectiveCamera(35, 1, 1e-5, size * 10);
    this.update(0);
    this.viewAll();
  }

  // The largest body or joint extent: sets the camera's reach and the marker sizes.
  extent() {
    let size = 0;
    for (const b of this.run.manifest.bodies) size = Math.max(size, ...b.box);
    for (const j of this.run.manifest.joints) size = Math.max(size, 4 * j.bearing_radius);
    return size || 1;
  }

  viewAll() {
    const box = new THREE.Box3();
    for (const [name, group] of this.bodies) if (name !== "ground") box.expandByObject(group);
    for (const j of this.joints) box.expandByObject(j.frame);
    const centre = box.getCenter(new THREE.Vector3());
    const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1e-3);
    const side = new THREE.Vector3(1, -1.6, 0.8).normalize();
    if (Math.abs(side.dot(this.up)) > 0.95) side.set(1, 0, 0);
    this.camera.position.copy(centre).addScaledVector(side, radius * 2.6);
    this.controls.target.copy(centre);
    this.controls.update();
  }

  focusJoint() {
    if (!this.joints.length) return;
    const j = this.joints[0];
    const centre = j.frame.getWorldPosition(new THREE.Vector3());
    const offset = this.camera.position.clone().sub(this.controls.target).setLength(8 * j.joint.bearing_radius);
    this.controls.target.copy(centre);
    this.camera.position.copy(centre).add(offset);
    this.controls.update();
  }

  setMagnification(factor) {
    return this.joints.map((j) => j.setMagnification(factor))[0] ?? 1;
  }

  update(frame) {
    const run = this.run;
    for (const b of run.manifest.bodies) {
      const group = this.bodies.get(b.name);
      const o = b.offset;
      group.position.set(run.value(frame, o), run.value(frame, o + 1), run.value(frame, o + 2));
      // Euler parameters (e0, e1, e2, e3) are the unit quaternion w, x, y, z of body to world.
      group.quaternion.set(run.value(frame, o + 4), run.value(frame, o + 5), run.value(frame, o + 6),
                           run.value(frame, o + 3)).normalize();
    }
    for (const j of this.joints) j.update(run, frame);
  }

  render() {
    const canvas = this.canvas;
    const width = canvas.clientWidth, height = canvas.clientHeight;
    if (canvas.width !== Math.floor(width * window.devicePixelRatio) ||
        canvas.height !== Math.floor(height * window.devicePixelRatio)) {
      this.renderer.setSize(width, height, false);
    }
    this.camera.aspect = width / Math.max(height, 1);
    this.camera.updateProjectionMatrix();
    this.renderer.setViewport(0, 0, width, height);
    this.renderer.setScissor(0, 0, width, height);
    this.renderer.render(this.scene, this.camera);
    if (this.joints.length) this.renderInset(width, height);
  }

  // A close-up of the first joint in its bearing's frame, bottom left: the camera moves with the
  // bearing, so the journal is seen moving relative to it, as in the orbit plot.
  renderInset(width, height) {
    const j = this.joints[0];
    const s = Math.floor(Math.min(width, height) * 0.36);
    const Ri = j.joint.bearing_radius;
    j.frame.updateWorldMatrix(true, false);
    // About 7 Ri away with a 35 degree field: the whole bearing (2 Ri across, Li long) fits.
    this.inset.position.copy(j.frame.localToWorld(new THREE.Vector3(2.5 * Ri, -2.8 * Ri, 5.8 * Ri)));
    this.inset.up.copy(new THREE.Vector3(0, 1, 0).transformDirection(j.frame.matrixWorld));
    this.inset.lookAt(j.frame.getWorldPosition(new THREE.Vector3()));
    this.inset.aspect = 1;
    this.inset.near = 0.05 * Ri;
    this.inset.far = 100 * Ri;
    this.inset.updateProjectionMatrix();
    this.renderer.setViewport(8, 8, s, s);
    this.renderer.setScissor(8, 8, s, s);
    const background = this.scene.background;
    this.scene.background = INSET_BACKGROUND;  // reads as a panel over the main view
    this.renderer.render(this.scene, this.inset);
    this.scene.background = background;
    this.insetSize = s;
  }
}
