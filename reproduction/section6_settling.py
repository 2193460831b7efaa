# SPDX-License-Identifier: BSD-3-Clause
"""The numbers behind the explanations of docs/reports/reproduction.md, from the store of
reproduction/studies/section6_settling.json: why the planar journal settles on the bearing wall, where the
spatial mechanism's energy goes, and what the impact-speed floor of eq. (28) changes.

Contact is read from the joint's `scenario` column (0: no contact) at the report times, so a
flight or a contact shorter than the report step (1e-5 s) is not seen.
"""
import numpy as np

NO_CONTACT = 0  # geometry::ContactScenario::none in force_<joint>.csv (docs/dynamics.md)
SETTLED_AFTER = 0.05  # [s] a window after the planar journal's first impacts (they end within ~10 ms)


def _series(store, run_id):
    return store.read(run_id)["time_series"]


def _force_table(series):
    names = [n for n in series if n.startswith("force_")]
    return series[names[0]] if names else None


def flights(time, scenario):
    """Free flight at the report times after the first contact: (report times, flights, last time)."""
    free = scenario == NO_CONTACT
    touched = np.flatnonzero(~free)
    if touched.size == 0:
        return 0, 0, float("nan")
    after = free[touched[0]:]
    starts = np.count_nonzero(after[1:] & ~after[:-1])
    last = float(time[touched[0]:][after][-1]) if after.any() else float("nan")
    return int(after.sum()), int(starts), last


def planar_settling(store, run_id):
    series = _series(store, run_id)
    force = _force_table(series)
    time, scenario = force["time"], force["scenario"].astype(int)
    free_reports, flight_count, last_free = flights(time, scenario)
    depth = force["line.depth"][time > SETTLED_AFTER]
    depth = depth[np.isfinite(depth)]
    total = series["energy"]["total"]
    return {"energy_loss_J": float(total[0] - total[-1]), "free_flight_reports": free_reports,
            "flights": flight_count, "last_free_flight_s": last_free, "reports": int(time.size),
            "line_depth_after_%gs_m" % SETTLED_AFTER: [float(depth.min()), float(depth.max())] if depth.size else None}


def contact_force(store, run_id):
    """The contact force on the journal in the plane of motion once the journal has settled on the
    wall (after SETTLED_AFTER): min, median, max of its magnitude [N]."""
    force = _force_table(_series(store, run_id))
    late = force["time"] > SETTLED_AFTER
    magnitude = np.hypot(force["fx"][late], force["fy"][late])
    return [float(magnitude.min()), float(np.median(magnitude)), float(magnitude.max())]


def crank_motion(store, run_id):
    """The spatial crank (turning about world y): angle turned, and when it first turns back."""
    series = _series(store, run_id)
    crank = series["body_crank"]
    time, rate = crank["time"], crank["wy"]
    angle = np.concatenate(([0.0], np.cumsum(0.5 * (rate[1:] + rate[:-1]) * np.diff(time))))
    back = np.flatnonzero(np.sign(rate) != np.sign(rate[0]))
    total = series["energy"]["total"]
    forces = {}
    force = _force_table(series)
    if force is not None:
        # Before the crank first turns back: the sum of the contacts' normal forces against the net
        # contact force the joint transmits (their difference is what pairs of opposite contacts
        # add to carry a moment, and what friction acts on).
        before = force["time"] < (time[back[0]] if back.size else np.inf)
        normal = sum(force[c] for c in force if c.endswith(".normal_force"))[before]
        net = np.sqrt(force["fx"] ** 2 + force["fy"] ** 2 + force["fz"] ** 2)[before]
        forces = {"normal_force_sum_mean_N": float(normal.mean()), "net_force_mean_N": float(net.mean())}
    return {"turns": float(angle[-1] / (2 * np.pi)), "largest_angle_rad": float(angle.max()), **forces,
            "turns_back_at_s": float(time[back[0]]) if back.size else None,
            "energy_loss_J": float(total[0] - total[-1]),
            "peak_acceleration": float(np.abs(series["body_slider"]["ax"]).max())}


def _run(settling, **values):
    """The run of the point of the study's own model with exactly these parameter values."""
    for point in settling.points:
        if not point.base and dict(point.values) == values:
            return settling.membership[(point.point_id, 0)]
    raise KeyError("section6_settling: no point %s" % values)


def summarise(settling):
    """settling: a StoreRuns of reproduction/studies/section6_settling.json."""
    store = settling.store
    out = {"planar_contact_force_N": contact_force(store, _run(settling, minimum_impact_speed=0.001)),
           "spatial_ideal": crank_motion(store, settling.run_id(design="spatial_ideal")),
           "spatial_frictionless": crank_motion(store, settling.run_id(design="spatial_frictionless")),
           "planar": {}, "spatial_impact_speed_floor": {}}
    for ce in (0.9, 0.95, 0.99, 1.0):
        out["planar"]["no friction, ce %g" % ce] = planar_settling(
            store, _run(settling, restitution=ce, friction_coefficient=0.0))
    for floor in (0.001, 0.01):
        out["planar"]["Table 2, floor %g m/s" % floor] = planar_settling(
            store, _run(settling, minimum_impact_speed=floor))
    for point in settling.points:
        if point.base == "spatial_impact_speed_floor":
            floor = dict(point.values)["minimum_impact_speed"]
            out["spatial_impact_speed_floor"]["%g" % floor] = crank_motion(
                store, settling.membership[(point.point_id, 0)])
    return out
