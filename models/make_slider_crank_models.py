#!/usr/bin/env python3
"""Writes the two ideal slider-crank model files of Marques et al. (2017), Tables 1 and 3.

The spatial model's rod orientation and slider position follow from the chosen geometry; computing
them here keeps the numbers in the JSON files exact to double precision and reproducible.
Run from this directory: python3 make_slider_crank_models.py
"""
import json
import math


def sub(a, b): return [x - y for x, y in zip(a, b)]
def add(a, b): return [x + y for x, y in zip(a, b)]
def scale(a, s): return [x * s for x in a]
def norm(a): return math.sqrt(sum(x * x for x in a))
def cross(a, b): return [a[1]*b[2] - a[2]*b[1], a[2]*b[0] - a[0]*b[2], a[0]*b[1] - a[1]*b[0]]


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


if __name__ == "__main__":
    for name, model in (("slider_crank_planar_ideal.json", planar()),
                        ("slider_crank_spatial_ideal.json", spatial())):
        with open(name, "w") as f:
            json.dump(model, f, indent=1)
            f.write("\n")
