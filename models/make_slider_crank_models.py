#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes the slider-crank model files of Marques et al. (2017), Section 6, Tables 1-3.

Ideal joints: slider_crank_planar_ideal.json, slider_crank_spatial_ideal.json.
With the revolute clearance joint (Table 2): slider_crank_planar_clearance_aligned.json,
slider_crank_planar_clearance_misaligned.json (rod turned 0.2 degrees about its own axis),
slider_crank_spatial_clearance.json. With the pin-in-hole joint of the same clearances (issue 48):
slider_crank_planar_clearance_pin_in_hole.json and slider_crank_spatial_pin_in_hole_misaligned.json
(the pin tilted in the ground, so that the crank's hole meets it at its edges); and the base model of the clearance studies of Sec. 6.2,
reproduction/models/slider_crank_spatial_clearance_study.json (cr = ca = 0.1 mm, the slider's
outputs only: the studies in reproduction/studies/ set the journal's radius and length of each
point, radial and axial clearance 0.05, 0.1, 0.3, 0.5 mm, when they run).

Orientations, positions and velocities follow from the chosen geometry; computing them here keeps
the numbers in the JSON files exact to double precision and reproducible.
Run from this directory: python3 make_slider_crank_models.py
"""
import json
import math
import os


def sub(a, b): return [x - y for x, y in zip(a, b)]
def add(a, b): return [x + y for x, y in zip(a, b)]
def scale(a, s): return [x * s for x in a]
def norm(a): return math.sqrt(sum(x * x for x in a))
def cross(a, b): return [a[1]*b[2] - a[2]*b[1], a[2]*b[0] - a[0]*b[2], a[0]*b[1] - a[1]*b[0]]


def quaternion_product(p, q):
    """Euler parameters of the rotation A(p) A(q) (q applied first, in p's body frame)."""
    p0, p1, p2, p3 = p
    q0, q1, q2, q3 = q
    return [p0*q0 - p1*q1 - p2*q2 - p3*q3,
            p0*q1 + p1*q0 + p2*q3 - p3*q2,
            p0*q2 - p1*q3 + p2*q0 + p3*q1,
            p0*q3 + p1*q2 - p2*q1 + p3*q0]


def axis_angle(axis, angle):
    s = math.sin(angle / 2)
    return [math.cos(angle / 2), axis[0] * s, axis[1] * s, axis[2] * s]


def rotate(p, v):
    """A(p) v for unit Euler parameters p."""
    e0, e = p[0], p[1:]
    t = scale(cross(e, v), 2)
    return add(add(v, scale(t, e0)), cross(e, t))


def euler_parameters(columns):
    """(e0, e1, e2, e3), e0 >= 0, of the rotation whose columns are the body axes in the world."""
    R = [[columns[c][r] for c in range(3)] for r in range(3)]
    e0 = math.sqrt(max(0.0, 1 + R[0][0] + R[1][1] + R[2][2])) / 2
    e1 = math.copysign(math.sqrt(max(0.0, 1 + R[0][0] - R[1][1] - R[2][2])) / 2, R[2][1] - R[1][2])
    e2 = math.copysign(math.sqrt(max(0.0, 1 - R[0][0] + R[1][1] - R[2][2])) / 2, R[0][2] - R[2][0])
    e3 = math.copysign(math.sqrt(max(0.0, 1 - R[0][0] - R[1][1] + R[2][2])) / 2, R[1][0] - R[0][1])
    n = norm([e0, e1, e2, e3])
    return [e0 / n, e1 / n, e2 / n, e3 / n]


SOLVER = {"comment": "Paper Table 2: ode45 (here Dormand-Prince 5(4) with dense output), reported step "
                     "1e-5 s, tolerance 1e-7, 1 s, Baumgarte alpha = beta = 5.",
          "start_time": 0.0, "end_time": 1.0, "report_step": 1e-5,
          "relative_tolerance": 1e-7, "absolute_tolerance": 1e-7,
          "baumgarte_alpha": 5.0, "baumgarte_beta": 5.0}


def planar():
    L1, L2 = 0.1524, 0.3048
    return {
        "name": "slider-crank with planar motion, ideal joints (Marques et al. 2017, Sec. 6.1, Table 1)",
        "notes": (
            "Ideal clearance-free version of the paper's first example: revolute ground-crank, spherical "
            "crank-rod, spherical rod-slider (the paper replaces the clearance revolute joint by a spherical "
            "joint to avoid redundant constraints) and translational slider-ground. Choices where the paper is "
            "silent: the mechanism moves in the world x-y plane, the crank turns about +z through the origin, "
            "the slider runs along the x axis; gravity is -9.81 m/s^2 along y so that it acts in the plane of "
            "motion. All body frames are aligned with the world frame at t = 0 (the paper's aligned case), crank "
            "and rod along +x (aligned), slider at x = L1 + L2 = 0.4572 m (final stroke position, top dead "
            "centre). Mass centres at the geometric centres. Table 1 is read column-wise (the PDF extraction "
            "lists each column): every body has equal principal moments (crank and rod 0.002, slider 0.001 "
            "kg m^2). Crank angular velocity 150 rad/s about +z; the others follow from the velocity "
            "constraints (rod spin about its own axis, a free motion between two spherical joints, stays zero)."),
        "gravity": [0.0, -9.81, 0.0],
        "bodies": [
            {"name": "crank", "mass": 0.15, "inertia": [0.002, 0.002, 0.002], "position": [L1 / 2, 0.0, 0.0],
             "angular_velocity": [0.0, 0.0, 150.0]},
            {"name": "rod", "mass": 0.30, "inertia": [0.002, 0.002, 0.002], "position": [L1 + L2 / 2, 0.0, 0.0]},
            {"name": "slider", "mass": 0.15, "inertia": [0.001, 0.001, 0.001], "position": [L1 + L2, 0.0, 0.0]}],
        "joints": [
            {"name": "crank-ground", "type": "revolute", "body_i": "ground", "body_j": "crank",
             "point_i": [0.0, 0.0, 0.0], "point_j": [-L1 / 2, 0.0, 0.0],
             "axis_i": [0.0, 0.0, 1.0], "axis_j": [0.0, 0.0, 1.0]},
            {"name": "crank-rod", "type": "spherical", "body_i": "crank", "body_j": "rod",
             "point_i": [L1 / 2, 0.0, 0.0], "point_j": [-L2 / 2, 0.0, 0.0]},
            {"name": "rod-slider", "type": "spherical", "body_i": "rod", "body_j": "slider",
             "comment": "the paper's revolute clearance joint, replaced by an ideal spherical joint",
             "point_i": [L2 / 2, 0.0, 0.0], "point_j": [0.0, 0.0, 0.0]},
            {"name": "slider-ground", "type": "translational", "body_i": "ground", "body_j": "slider",
             "point_i": [0.0, 0.0, 0.0], "point_j": [0.0, 0.0, 0.0],
             "axis_i": [1.0, 0.0, 0.0], "axis_j": [1.0, 0.0, 0.0]}],
        "initial_conditions": {
            "comment": "crank pose held; the rest is corrected by Newton-Raphson (the guess is already exact)",
            "hold_positions": [{"body": "crank", "components": ["x", "y", "z", "rx", "ry", "rz"]}],
            "hold_velocities": [{"body": "crank", "component": "wz", "value": 150.0}]},
        "solver": SOLVER,
        "output": {"bodies": ["crank", "rod", "slider"]}}


def spatial():
    Lc, Lr, offset = 0.10, 0.29, 0.12
    C = [0.0, 0.0, Lc]                                     # crank pin, crank vertical
    S = [math.sqrt(Lr**2 - offset**2 - Lc**2), offset, 0.0]  # slider at t = 0
    eta = scale(sub(S, C), 1 / norm(sub(S, C)))            # rod axis, crank pin -> slider
    xi = cross(eta, [0.0, 0.0, 1.0])
    xi = scale(xi, 1 / norm(xi))
    zeta = cross(xi, eta)
    return {
        "name": "slider-crank with spatial motion, ideal joints (Marques et al. 2017, Sec. 6.2, Table 3)",
        "notes": (
            "Ideal version of the paper's second example: revolute ground-crank (the paper's clearance joint, "
            "ideal here), spherical crank-rod, universal rod-slider, translational slider-ground; gravity "
            "-9.81 m/s^2 along z (paper). The paper gives no coordinates for Fig. 12; choices made here: the "
            "crank pivot is at the origin and the crank turns about +y (paper: 2 pi rad/s about +y) in the x-z "
            "plane, vertical (+z) at t = 0. The slider runs along x on a guide through (0, 0.12, 0), offset "
            "0.12 m from the crank plane so that the rod moves out of any plane; at t = 0 the slider is at "
            "x = sqrt(0.29^2 - 0.12^2 - 0.10^2) = 0.24434 m. Body frames: crank and slider aligned with the "
            "world frame; the rod's eta axis (Table 3's small moment 0.0004) points from the crank pin to the "
            "slider, its xi axis is eta x z (normalised) and is the universal joint's cross axis on the rod; "
            "the cross axis on the slider is its z axis. Table 3 is read column-wise (PDF extraction: "
            "'0.0 0 01' = 0.0001, '0.0 0 0 01' = 0.00001): crank (1e-4, 1e-4, 1e-5) with its long axis along "
            "zeta, rod (0.004, 0.0004, 0.004), slider 1e-4 each. Mass centres at the geometric centres."),
        "gravity": [0.0, 0.0, -9.81],
        "bodies": [
            {"name": "crank", "mass": 0.12, "inertia": [1e-4, 1e-4, 1e-5], "position": [0.0, 0.0, Lc / 2],
             "angular_velocity": [0.0, 2 * math.pi, 0.0]},
            {"name": "rod", "mass": 0.50, "inertia": [0.004, 0.0004, 0.004], "position": scale(add(C, S), 0.5),
             "euler_parameters": euler_parameters([xi, eta, zeta])},
            {"name": "slider", "mass": 0.50, "inertia": [1e-4, 1e-4, 1e-4], "position": S}],
        "joints": [
            {"name": "crank-ground", "type": "revolute", "body_i": "ground", "body_j": "crank",
             "point_i": [0.0, 0.0, 0.0], "point_j": [0.0, 0.0, -Lc / 2],
             "axis_i": [0.0, 1.0, 0.0], "axis_j": [0.0, 1.0, 0.0]},
            {"name": "crank-rod", "type": "spherical", "body_i": "crank", "body_j": "rod",
             "point_i": [0.0, 0.0, Lc / 2], "point_j": [0.0, -Lr / 2, 0.0]},
            {"name": "rod-slider", "type": "universal", "body_i": "rod", "body_j": "slider",
             "point_i": [0.0, Lr / 2, 0.0], "point_j": [0.0, 0.0, 0.0],
             "axis_i": [1.0, 0.0, 0.0], "axis_j": [0.0, 0.0, 1.0]},
            {"name": "slider-ground", "type": "translational", "body_i": "ground", "body_j": "slider",
             "point_i": [0.0, offset, 0.0], "point_j": [0.0, 0.0, 0.0],
             "axis_i": [1.0, 0.0, 0.0], "axis_j": [1.0, 0.0, 0.0]}],
        "initial_conditions": {
            "comment": "crank pose (vertical) and angular velocity held; rod and slider follow",
            "hold_positions": [{"body": "crank", "components": ["x", "y", "z", "rx", "ry", "rz"]}],
            "hold_velocities": [{"body": "crank", "component": "wy", "value": 2 * math.pi}]},
        "solver": SOLVER,
        "output": {"bodies": ["crank", "rod", "slider"]}}


# Table 2 of the paper. Ri, Li are the bearing's radius and length, Rj, Lj the journal's.
TABLE2_NOTES = (
    "Clearance joint (paper Table 2): Ri = 10 mm, Rj = 9.9 mm, Li = 20.0 mm, Lj = 19.8 mm (radial and "
    "axial clearance 0.1 mm), K = 1e11 N/m^1.5 (the extraction reads '1011 N/m3/2': 10^11), exponent 1.5 "
    "(Sec. 4, metallic contact), restitution ce = 0.9 with the Lankarani-Nikravesh law (eqs. 27-29), friction "
    "mu_k = 0.1 and k = 1000 s/m (eq. 32; the extraction reads '10 0 0 s/m'), Baumgarte alpha = beta = 5, "
    "ode45 (here Dormand-Prince 5(4)), reported step 1e-5 s, tolerance 1e-7, 1 s. Not in the paper: "
    "minimum_impact_speed = 1e-3 m/s, a floor on the impact velocity in the damping coefficient (see "
    "docs/dynamics.md); the detection decides parallel axes exactly (eq. 5), parallel_angle_tolerance 0.")


def clearance_joint(name, bearing_body, bearing_point, journal_body, journal_point, axis_bearing,
                    axis_journal, radial_clearance=1e-4, axial_clearance=1e-4):
    Ri, Li = 0.010, 0.020
    return {"type": "clearance_revolute", "name": name,
            "comment": "paper Table 2; the study varies the journal (Rj = Ri - cr, Lj = Li - 2 ca), the bearing stays",
            "bearing": {"body": bearing_body, "point": bearing_point, "axis": axis_bearing,
                        "radius": Ri, "length": Li},
            "journal": {"body": journal_body, "point": journal_point, "axis": axis_journal,
                        "radius": Ri - radial_clearance, "length": Li - 2 * axial_clearance},
            "normal_force": {"model": "lankarani_nikravesh", "stiffness": 1e11, "exponent": 1.5,
                             "restitution": 0.9, "minimum_impact_speed": 1e-3},
            "friction": {"coefficient": 0.1, "velocity_coefficient": 1000.0},
            "detection": {"parallel_angle_tolerance": 0.0}}


# The pin's heads: washers of 1.5 times the hole's radius, a common washer-to-bore ratio; their
# faces stand ca beyond the link's faces, so the axial play is the paper's ca.
HEAD_RADIUS_OVER_HOLE = 1.5


def pin_in_hole_joint(name, hole_body, hole_point, pin_body, pin_point, axis_hole, axis_pin,
                      radial_clearance=1e-4, axial_clearance=1e-4):
    """The joint of clearance_joint() as a pin through a hole (docs/dynamics.md): the hole is the
    bearing (Rh = Ri, L = Li), the pin the journal (Rp = Rh - cr) with a head on each side."""
    joint = clearance_joint(name, hole_body, hole_point, pin_body, pin_point, axis_hole, axis_pin,
                            radial_clearance, axial_clearance)
    hole, journal = joint.pop("bearing"), joint.pop("journal")
    head = {"position": hole["length"] / 2 + axial_clearance,
            "outer_radius": HEAD_RADIUS_OVER_HOLE * hole["radius"]}
    pin = {key: journal[key] for key in ("body", "point", "axis", "radius")}
    pin["stops"] = [head, dict(head, position=-head["position"])]
    return dict({"type": joint.pop("type"), "name": joint.pop("name"), "geometry": "pin_in_hole",
                 "comment": "paper Table 2 clearances: Rp = Rh - cr, heads' faces ca beyond the link's faces",
                 "hole": hole, "pin": pin}, **{k: v for k, v in joint.items() if k != "comment"})


def planar_clearance(misalignment_degrees):
    """Sec. 6.1 with the clearance joint between the rod (journal) and the slider (bearing)."""
    L1, L2 = 0.1524, 0.3048
    # Rod frame: eta (body y) along the rod, from the crank pin to the slider, as the paper's
    # Fig. 11 reads the rod's rotation about its own axis from its third Euler parameter e2 ("over
    # eta_2"); zeta (body z) normal to the plane of motion, the journal's axis; xi = eta x zeta.
    # That is a rotation of -90 degrees about z, then the misalignment about the rod's own eta.
    aligned = axis_angle([0.0, 0.0, 1.0], -math.pi / 2)
    rod_p = quaternion_product(aligned, axis_angle([0.0, 1.0, 0.0], math.radians(misalignment_degrees)))
    # Velocities of the ideal mechanism at top dead centre: crank 150 rad/s about +z, crank pin
    # 150 L1 along +y, rod -150 L1 / L2 = -75 rad/s about +z, slider at rest.
    rod_omega_W = [0.0, 0.0, -150.0 * L1 / L2]
    rod_omega_B = rotate([rod_p[0], -rod_p[1], -rod_p[2], -rod_p[3]], rod_omega_W)
    case = "aligned" if misalignment_degrees == 0 else \
        "misaligned: rod turned %g degrees about its own axis" % misalignment_degrees
    return {
        "name": "slider-crank with planar motion and a revolute clearance joint rod-slider, %s "
                "(Marques et al. 2017, Sec. 6.1, Tables 1-2)" % case,
        "notes": (
            "The paper's first example: revolute ground-crank, spherical crank-rod, revolute clearance joint "
            "between the connecting rod (journal) and the slider (bearing), translational slider-ground. Same "
            "geometry, gravity and Table 1 reading as slider_crank_planar_ideal.json (plane x-y, crank about +z, "
            "slider along x, gravity -y, crank and rod along +x, slider at x = 0.4572 m, top dead centre). "
            "The rod's body frame has its eta axis (body y) along the rod so that its rotation about its own "
            "axis shows in the third Euler parameter e2 (paper Fig. 11); the journal's axis is the rod's zeta "
            "(body z), the bearing's axis the slider's z: parallel in the aligned case. Misaligned case: the "
            "rod is turned %g degrees about eta, which tilts the journal %g degrees from the bearing axis. "
            "The journal starts centred in the bearing. Initial velocities: crank 150 rad/s about +z held; "
            "rod (0, 11.43, 0) m/s and -75 rad/s about +z, slider at rest, the ideal mechanism's values "
            "(they satisfy the ideal joints, so the corrector leaves them). " % (
                misalignment_degrees, misalignment_degrees) + TABLE2_NOTES),
        "gravity": [0.0, -9.81, 0.0],
        "bodies": [
            {"name": "crank", "mass": 0.15, "inertia": [0.002, 0.002, 0.002], "position": [L1 / 2, 0.0, 0.0],
             "angular_velocity": [0.0, 0.0, 150.0]},
            {"name": "rod", "mass": 0.30, "inertia": [0.002, 0.002, 0.002], "position": [L1 + L2 / 2, 0.0, 0.0],
             "euler_parameters": rod_p, "velocity": [0.0, 150.0 * L1 / 2, 0.0], "angular_velocity": rod_omega_B},
            {"name": "slider", "mass": 0.15, "inertia": [0.001, 0.001, 0.001], "position": [L1 + L2, 0.0, 0.0]}],
        "joints": [
            {"name": "crank-ground", "type": "revolute", "body_i": "ground", "body_j": "crank",
             "point_i": [0.0, 0.0, 0.0], "point_j": [-L1 / 2, 0.0, 0.0],
             "axis_i": [0.0, 0.0, 1.0], "axis_j": [0.0, 0.0, 1.0]},
            {"name": "crank-rod", "type": "spherical", "body_i": "crank", "body_j": "rod",
             "point_i": [L1 / 2, 0.0, 0.0], "point_j": [0.0, -L2 / 2, 0.0]},
            {"name": "slider-ground", "type": "translational", "body_i": "ground", "body_j": "slider",
             "point_i": [0.0, 0.0, 0.0], "point_j": [0.0, 0.0, 0.0],
             "axis_i": [1.0, 0.0, 0.0], "axis_j": [1.0, 0.0, 0.0]}],
        "forces": [clearance_joint("rod-slider clearance", "slider", [0.0, 0.0, 0.0], "rod",
                                   [0.0, L2 / 2, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, 1.0])],
        "initial_conditions": {
            "comment": "crank pose and angular velocity held; the other guesses already satisfy the joints",
            "hold_positions": [{"body": "crank", "components": ["x", "y", "z", "rx", "ry", "rz"]}],
            "hold_velocities": [{"body": "crank", "component": "wz", "value": 150.0}]},
        "solver": SOLVER,
        "output": {"bodies": ["crank", "rod", "slider"]}}


# The oil of the lubricated Sec. 6.1 (issue 36; docs/lubrication.md): eta = 0.04 Pa s, an ISO VG 46
# machine or hydraulic oil at its 40 degrees C rating (46 mm^2/s, 870 kg/m^3), the ordinary oil of a
# plain bushing of this size. With it the squeeze film carries the slider's reversals (about 300 N
# of inertia load) with eps at most about 0.8 and h_min above 15 um, so the journal never reaches
# the wall. The film would give way to the dry contact law below h_l = 2 um (a few times the
# combined roughness, Ra ~ 0.4 um, of a ground journal in a honed bushing), faded in over the next
# 2 um. Short-bearing (Ocvirk) closed form: B/D = 1 lies outside its range (it overestimates the
# load, docs/lubrication.md), but it costs under a microsecond, against 0.3 ms for the 48 x 12 grid.
LUBRICATION = {"comment": "ISO VG 46 oil at 40 C; see make_slider_crank_models.py",
               "viscosity": 0.04, "cavitation": "half_sommerfeld", "method": "short",
               "film_thickness_limit": 2e-6, "transition_width": 2e-6}


def planar_lubricated():
    """Sec. 6.1 aligned, with the clearance joint lubricated (LUBRICATION)."""
    model = planar_clearance(0.0)
    model["name"] = ("slider-crank with planar motion and a lubricated revolute clearance joint "
                     "rod-slider, aligned (Marques et al. 2017, Sec. 6.1, Tables 1-2; oil film: issue 36)")
    model["notes"] = (
        "slider_crank_planar_clearance_aligned.json with an oil film in its clearance joint: viscosity "
        "0.04 Pa s (an ISO VG 46 oil at 40 C), short-bearing (Ocvirk) film with the half-Sommerfeld "
        "condition, dry contact law (unchanged) once the film is thinner than 2 um, faded over 2 um "
        "(docs/lubrication.md, Lubricated Section 6.1). Dry model notes: " + model["notes"])
    model["forces"][0]["lubrication"] = LUBRICATION
    return model


def planar_pin_in_hole():
    """Sec. 6.1 aligned with the rod-slider joint a pin (in the rod) through a hole (in the slider)."""
    model = planar_clearance(0.0)
    model["name"] = ("slider-crank with planar motion and a pin-in-hole clearance joint rod-slider, aligned "
                     "(Marques et al. 2017, Sec. 6.1, Tables 1-2; pin-in-hole joint: issue 48)")
    model["notes"] = (
        "slider_crank_planar_clearance_aligned.json with its clearance joint built as a pin through a hole "
        "(docs/dynamics.md, The pin-in-hole geometry): the hole (Rh = 10 mm, 20 mm long) in the slider, "
        "the pin (Rp = 9.9 mm) in the rod with a head on each side whose face stands 0.1 mm beyond the "
        "link's face (outer radius 15 mm): the same radial and axial clearances, 0.1 mm. Same force laws "
        "and friction. Paper model notes: " + model["notes"])
    old = model["forces"][0]
    model["forces"] = [pin_in_hole_joint("rod-slider pin", old["bearing"]["body"], old["bearing"]["point"],
                                         old["journal"]["body"], old["journal"]["point"],
                                         old["bearing"]["axis"], old["journal"]["axis"])]
    return model


# The pin's tilt in the spatial pin-in-hole model: 0.3 degrees, below the 2 cr / L = 0.01 rad
# (0.57 degrees) at which a centred pin would touch both edges of the hole, so that it starts free.
PIN_TILT_DEGREES = 0.3


def spatial_pin_in_hole_misaligned():
    """Sec. 6.2 with the ground-crank joint a pin (in the ground, tilted) through a hole (in the crank)."""
    model = spatial_clearance()
    tilt = math.radians(PIN_TILT_DEGREES)
    model["name"] = ("slider-crank with spatial motion and a misaligned pin-in-hole clearance joint "
                     "ground-crank (Marques et al. 2017, Sec. 6.2, Tables 2-3; pin-in-hole joint: issue 48)")
    model["notes"] = (
        "slider_crank_spatial_clearance.json with its clearance joint built as a pin through a hole "
        "(docs/dynamics.md, The pin-in-hole geometry): the hole (Rh = 10 mm, 20 mm long) in the crank, the "
        "pin (Rp = 9.9 mm, heads 0.1 mm beyond the link's faces) in the ground, its axis tilted %g degrees "
        "from y about x, so that the hole meets it at its edges (scenarios one_edge, both_edges_*). Paper "
        "model notes: " % PIN_TILT_DEGREES + model["notes"])
    old = model["forces"][0]
    model["forces"] = [pin_in_hole_joint("ground-crank pin", old["bearing"]["body"], old["bearing"]["point"],
                                         old["journal"]["body"], old["journal"]["point"], old["bearing"]["axis"],
                                         [0.0, math.cos(tilt), math.sin(tilt)])]
    return model


def spatial_clearance(radial_clearance=1e-4, axial_clearance=1e-4, study=False):
    """Sec. 6.2 with the clearance joint between the ground (journal) and the crank (bearing)."""
    model = spatial()
    Lc = 0.10
    w = 2 * math.pi
    model["name"] = ("slider-crank with spatial motion and a revolute clearance joint ground-crank, "
                     "cr = %g mm, ca = %g mm (Marques et al. 2017, Sec. 6.2, Tables 2-3)" % (
                         radial_clearance * 1e3, axial_clearance * 1e3))
    model["notes"] = (
        "The paper's second example with its clearance joint: the revolute ground-crank joint of "
        "slider_crank_spatial_ideal.json is replaced by a revolute clearance joint, bearing in the crank (at "
        "its pivot end, axis along the crank's y), journal in the ground (at the origin, axis y). Geometry, "
        "gravity, Table 3 reading and the other joints as in the ideal model (its notes follow). Initial "
        "conditions: the ideal mechanism's (paper: 'the remaining coordinates and velocities are calculated in "
        "such a way that the kinematic constraints of an ideal mechanism are fulfilled'): the journal starts "
        "centred and aligned in the bearing, the crank vertical turning at 2 pi rad/s about +y about the "
        "journal's centre; all six crank velocities are held at those values and the rod and slider follow. "
        "Radial clearance cr = Ri - Rj = %g mm, axial clearance ca = (Li - Lj)/2 = %g mm. " % (
            radial_clearance * 1e3, axial_clearance * 1e3) + TABLE2_NOTES + " Ideal model notes: " +
        model["notes"])
    model["joints"] = [j for j in model["joints"] if j["name"] != "crank-ground"]
    model["forces"] = [clearance_joint("ground-crank clearance", "crank", [0.0, 0.0, -Lc / 2], "ground",
                                       [0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 1.0, 0.0],
                                       radial_clearance, axial_clearance)]
    model["initial_conditions"] = {
        "comment": "crank vertical, centred on the journal, 2 pi rad/s about +y: v = w x r = (2 pi 0.05, 0, 0)",
        "hold_positions": [{"body": "crank", "components": ["x", "y", "z", "rx", "ry", "rz"]}],
        "hold_velocities": [{"body": "crank", "component": c, "value": v} for c, v in
                            (("vx", w * Lc / 2), ("vy", 0.0), ("vz", 0.0), ("wx", 0.0), ("wy", w),
                             ("wz", 0.0))]}
    if study:
        model["output"] = {"bodies": ["slider"], "force_elements": [],
                           "comment": "the study needs the slider only; the joint's outputs are skipped"}
    return model


HERE = os.path.dirname(os.path.abspath(__file__))
REPOSITORY = os.path.dirname(HERE)


def model_files():
    """Every model file this script writes: its path relative to the repository, and the model."""
    files = {os.path.join("models", name): model for name, model in (
        ("slider_crank_planar_ideal.json", planar()),
        ("slider_crank_spatial_ideal.json", spatial()),
        ("slider_crank_planar_clearance_aligned.json", planar_clearance(0.0)),
        ("slider_crank_planar_clearance_misaligned.json", planar_clearance(0.2)),
        ("slider_crank_planar_clearance_lubricated.json", planar_lubricated()),
        ("slider_crank_spatial_clearance.json", spatial_clearance()),
        ("slider_crank_planar_clearance_pin_in_hole.json", planar_pin_in_hole()),
        ("slider_crank_spatial_pin_in_hole_misaligned.json", spatial_pin_in_hole_misaligned()))}
    files[os.path.join("reproduction", "models", "slider_crank_spatial_clearance_study.json")] = \
        spatial_clearance(study=True)
    return files


def write(path, model):
    with open(path, "w") as f:
        json.dump(model, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    for relative, model in model_files().items():
        write(os.path.join(REPOSITORY, relative), model)
