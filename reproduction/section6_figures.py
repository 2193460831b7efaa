# SPDX-License-Identifier: BSD-3-Clause
"""Figures 7-11 and 13-19 of Marques et al. (2017), Section 6, from the reduced runs of
reproduce_section6.py, and the numbers docs/reports/reproduction.md quotes.

Every figure is drawn from data, nothing is hand-placed. The figures of one run (Figs. 7-11,
13-18) are drawn with clearjoint.plot's panels, as `clearjoint plot` draws a run folder: the
clearance run's curves coloured by the contact scenario of each report time (the one colour
table, clearjoint.plot.SCENARIO_COLOURS), the ideal joint's dashed, the journal's orbits in units
of the radial clearance with the impacts marked. The figures of the study (Fig. 19 and the
statistics against clearance) are drawn here; they colour sweeps, not scenarios, with the study
plot's colours. Units: m, m/s, m/s^2, J, s; clearances in mm in labels. Slider quantities are the
world-x components of its position, velocity and acceleration (the slider runs along x in both
mechanisms).
"""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from clearjoint import plot as runplot  # noqa: E402
from clearjoint.plot.panels import IDEAL_CURVE  # noqa: E402
from clearjoint.study.plot import COLOURS as SWEEP_COLOURS  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from section6_settling import flights  # noqa: E402
from mpl_toolkits.mplot3d import Axes3D  # noqa: E402,F401 (registers the 3d projection)

# Sec. 6.1: "the outputs only report a portion of the total simulations performed, which represents
# a steady-state behavior following the initial impacts". The paper does not say which portion;
# 0.1-0.2 s is shown here: the journal has been in continuous contact since its first milliseconds
# (docs/reports/reproduction.md, Sec. 6.1), and the misaligned journal's tilt has fallen from 0.2 to
# below 1e-3 degrees. Later windows look the same except for a larger lag (friction in the joint
# keeps removing energy from the free-running mechanism).
PLANAR_WINDOW = (0.1, 0.2)
# Fig. 14: "only data on the first 0.20 s is displayed".
TRAJECTORY_WINDOW = 0.20
SLIDER = (("x", "slider position [m]"), ("vx", "slider velocity [m/s]"),
          ("ax", "slider acceleration [m/s$^2$]"))


def window(run, t0, t1):
    mask = (run["time"] >= t0) & (run["time"] <= t1)
    return {k: (v[mask] if np.ndim(v) == 1 and len(v) == len(mask) else v) for k, v in run.items()}


def save(fig, figures, name):
    path = os.path.join(figures, name)
    partial = path + ".partial.png"
    fig.savefig(partial, dpi=110)
    plt.close(fig)
    os.replace(partial, path)


def joint_of(run, start=None, end=None):
    """The run's clearance joint as clearjoint.plot reads it (the stored tables and model)."""
    stored = runplot.read_run(run["tables"], run["model"])
    return runplot.joint_series(stored, stored.clearance_tables()[0], (start, end))


# A clearance run whose store keeps no joint table (the clearance study's model writes none) is
# drawn in one colour that is no scenario's.
UNCOLOURED = "0.15"


def compared(ax, run, ideal, x_key, y_key, x_label, y_label, x_scale=1.0):
    """One panel of the clearance run against the ideal one, coloured by scenario when the
    run's joint table is stored."""
    runplot.plot_compared(ax, run[x_key] * x_scale, run[y_key], x_label, y_label,
                          None if ideal is None else ideal[x_key] * x_scale,
                          None if ideal is None else ideal[y_key],
                          scenario=run.get("joint_scenario"), colour=UNCOLOURED, legend=False)


def scenario_legend(ax, runs, ideal=True, impacts=False, title="clearance joint: contact scenario"):
    """The legend of the scenarios the runs visit (and the ideal joint's curve), beside ``ax``."""
    codes = np.concatenate([np.asarray(r["joint_scenario"], dtype=int) for r in runs])
    handles = runplot.scenario_legend_handles(codes, with_impacts=impacts)
    if ideal:
        handles.insert(0, Line2D([], [], label="ideal joint", **IDEAL_CURVE))
    ax.legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0),
              borderaxespad=0.0, title=title + " (Fig. 2)", title_fontsize=7)


def label_panels(axes):
    for ax, letter in zip(axes, "abcdef"):
        ax.set_title("(%s)" % letter, loc="left", fontsize=9)


def slider_kinematics(figures, name, title, ideal, clearance):
    """Figs. 7 and 8: slider position, velocity, acceleration against time."""
    fig, axes = plt.subplots(3, 1, figsize=(8.5, 8), sharex=True, constrained_layout=True)
    for ax, (key, label) in zip(axes, SLIDER):
        compared(ax, clearance, ideal, "time", key, "", label)
    axes[-1].set_xlabel("time [s]")
    label_panels(axes)
    scenario_legend(axes[0], [clearance])
    fig.suptitle(title, fontsize=10)
    save(fig, figures, name)


def phase_portraits(figures, name, title, ideal, clearance):
    """Figs. 9 and 10: velocity against position, acceleration against velocity."""
    fig, axes = plt.subplots(1, 2, figsize=(11.5, 4.4), constrained_layout=True)
    compared(axes[0], clearance, ideal, "x", "vx", SLIDER[0][1], SLIDER[1][1])
    compared(axes[1], clearance, ideal, "vx", "ax", SLIDER[1][1], SLIDER[2][1])
    label_panels(axes)
    scenario_legend(axes[1], [clearance])
    fig.suptitle(title, fontsize=10)
    save(fig, figures, name)


def initial_impacts(figures, ideal, aligned, misaligned, end=0.012):
    """Extra (not in the paper): the impacts before continuous contact, aligned and misaligned."""
    fig, axes = plt.subplots(2, 1, figsize=(9, 6), sharex=True, sharey=True, constrained_layout=True)
    reference = window(ideal, 0.0, end)
    for ax, run, label, letter in zip(axes, (aligned, misaligned), ("aligned", "misaligned 0.2$^\\circ$"), "ab"):
        part = window(run, 0.0, end)
        compared(ax, part, reference, "time", "ax", "", SLIDER[2][1], x_scale=1e3)
        ax.set_title("(%s) %s: peak |a| = %.0f m/s$^2$" % (letter, label, np.abs(part["ax"]).max()),
                     loc="left", fontsize=9)
        scenario_legend(ax, [part])
    axes[-1].set_xlabel("time [ms]")
    fig.suptitle("Planar slider-crank: the first %g ms (the impacts before continuous contact)" % (end * 1e3),
                 fontsize=10)
    save(fig, figures, "fig07_08_initial_impacts.png")


def rod_rotation(figures, aligned, misaligned):
    """Fig. 11: the rod's third Euler parameter e2, and the angle between journal and bearing."""
    fig, axes = plt.subplots(2, 1, figsize=(8.5, 6.5), sharex=True, constrained_layout=True)
    runplot.plot_compared(axes[0], misaligned["time"], misaligned["rod_e2"], "", "rod Euler parameter $e_2$",
                          aligned["time"], aligned["rod_e2"], scenario=misaligned["joint_scenario"],
                          reference_label="aligned", legend=False)
    runplot.plot_tilt(axes[1], joint_of(misaligned), misaligned["time"], "time [s]", log=True)
    axes[1].set_ylabel("angle journal-bearing [deg]")
    label_panels(axes)
    handles = [Line2D([], [], label="aligned", **IDEAL_CURVE)] + runplot.scenario_legend_handles(
        misaligned["joint_scenario"], with_impacts=False)
    axes[0].legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0,
                   title="misaligned (rod turned 0.2$^\\circ$\nabout its axis): scenario", title_fontsize=7)
    fig.suptitle("Fig. 11: rod rotation about its own axis (planar slider-crank)", fontsize=10)
    save(fig, figures, "fig11.png")


def spatial_comparison(figures, ideal, clearance):
    """Fig. 13: slider motion, energy, phase portraits; ideal against clearance joint."""
    fig, axes = plt.subplots(3, 2, figsize=(12.5, 10), constrained_layout=True)
    energy = "mechanical energy $E - E_0$ [J]"
    panels = [("time", "x", "time [s]", SLIDER[0][1]), ("time", "vx", "time [s]", SLIDER[1][1]),
              ("time", "ax", "time [s]", SLIDER[2][1]), ("time", "dE", "time [s]", energy),
              ("x", "vx", SLIDER[0][1], SLIDER[1][1]), ("vx", "ax", SLIDER[1][1], SLIDER[2][1])]
    for run in (ideal, clearance):
        run["dE"] = run["total"] - run["total"][0]
    for ax, (xk, yk, xl, yl) in zip(axes.T.flat, panels):
        compared(ax, clearance, ideal, xk, yk, xl, yl)
    label_panels(axes.T.flat)
    scenario_legend(axes[0, 1], [clearance])
    fig.suptitle("Fig. 13: spatial slider-crank, ideal and clearance joint (Table 2, with friction)",
                 fontsize=10)
    save(fig, figures, "fig13.png")


def journal_trajectories(figures, clearance):
    """Fig. 14: centres of the journal bases relative to the bearing, first 0.2 s: each in the
    bearing's cross-section (clearjoint.plot's orbit), both in an isometric view."""
    series = joint_of(clearance, 0.0, TRAJECTORY_WINDOW)
    fig = plt.figure(figsize=(16, 5.6), constrained_layout=True)
    grid = fig.add_gridspec(1, 3, width_ratios=(1.0, 1.0, 1.2))
    runplot.plot_orbit(fig.add_subplot(grid[0, 0]), series, "a")
    runplot.plot_orbit(fig.add_subplot(grid[0, 1]), series, "b")
    ax3 = fig.add_subplot(grid[0, 2], projection="3d")
    runplot.plot_orbit_3d(ax3, series)
    ax3.set_box_aspect((1.0, 1.0, 1.3))
    ax3.set_title("isometric view, base centres at both ends (c$_a$ = %g mm each side)" % (
        series.axial_clearance * 1e3), fontsize=9)
    fig.axes[1].legend(handles=runplot.scenario_legend_handles(series.scenario), fontsize=7, loc="upper left",
                       bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0, title="contact scenario (Fig. 2)",
                       title_fontsize=7)
    fig.suptitle("Fig. 14: trajectories of the centres of the journal bases relative to the bearing "
                 "(u, v in units of c$_r$ = %g mm), first %.2f s" % (series.radial_clearance * 1e3,
                                                                       TRAJECTORY_WINDOW), fontsize=10)
    save(fig, figures, "fig14.png")


def sweep_panels(figures, name, title, runs, labels, kind):
    """Figs. 15-18: one panel per clearance, acceleration against time or against velocity."""
    fig, axes = plt.subplots(2, 2, figsize=(12.5, 7.5), sharex=True, sharey=True, constrained_layout=True)
    for ax, run, label, letter in zip(axes.flat, runs, labels, "abcd"):
        if kind == "time":
            compared(ax, run, None, "time", "ax", "time [s]", SLIDER[2][1])
        else:
            compared(ax, run, None, "vx", "ax", SLIDER[1][1], SLIDER[2][1])
        ax.set_title("(%s) %s, peak |a| = %.0f m/s$^2$" % (letter, label, np.abs(run["ax"]).max()),
                     loc="left", fontsize=9)
    for ax in axes[0]:
        ax.set_xlabel("")
    for ax in axes[:, 1]:
        ax.set_ylabel("")
    if all("joint_scenario" in run for run in runs):
        scenario_legend(axes[0, 1], runs, ideal=False, title="contact scenario")
    else:
        title += " (the study's runs keep no joint table: not coloured by scenario)"
    fig.suptitle(title, fontsize=10)
    save(fig, figures, name)


def peak_surface(figures, name, title, clearances_mm, peaks):
    """Fig. 19: peak slider acceleration over the radial x axial clearance grid."""
    fig = plt.figure(figsize=(8, 6.5))
    ax = fig.add_subplot(projection="3d")
    cr, ca = np.meshgrid(clearances_mm, clearances_mm, indexing="ij")
    ax.plot_surface(cr, ca, peaks, cmap="viridis", edgecolor="k", linewidth=0.4, alpha=0.85)
    for i in range(len(clearances_mm)):
        for j in range(len(clearances_mm)):
            ax.text(cr[i, j], ca[i, j], peaks[i, j], "%.0f" % peaks[i, j], fontsize=7)
    ax.set_xlabel("radial clearance [mm]")
    ax.set_ylabel("axial clearance [mm]")
    ax.set_zlabel("peak |slider acceleration| [m/s$^2$]")
    ax.set_title(title, fontsize=10)
    save(fig, figures, name)


def peaks_against_clearance(figures, clearances_mm, grids, tolerances, end_time):
    """Extra (not in the paper): the sweep statistics of Figs. 15-16 and 19 as lines, at the
    paper's tolerance (solid) and a tenth of it (dotted); the sweeps in the colours of the
    ensemble figures (clearjoint.study.plot)."""
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.3))
    k01 = list(clearances_mm).index(0.1)
    for (stats, tolerance), style in zip(zip(grids, tolerances), ("-", ":")):
        for ax, grid in zip(axes, stats):
            ax.plot(clearances_mm, grid[:, k01], "o" + style, color=SWEEP_COLOURS[0],
                    label="c$_r$ varied, c$_a$ = 0.1 mm, tol %g" % tolerance)
            ax.plot(clearances_mm, grid[k01, :], "s" + style, color=SWEEP_COLOURS[1],
                    label="c$_a$ varied, c$_r$ = 0.1 mm, tol %g" % tolerance)
            ax.plot(clearances_mm, np.diag(grid), "^" + style, color=SWEEP_COLOURS[2],
                    label="c$_r$ = c$_a$, tol %g" % tolerance)
    for ax, label in zip(axes, ("peak |a|", "99.9th percentile of |a|", "RMS of a")):
        ax.set_xlabel("clearance [mm]")
        ax.set_ylabel(label + " [m/s$^2$]")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=6)
    fig.suptitle("Slider acceleration statistics over %g s against clearance (spatial slider-crank); "
                 "solid: tolerance 1e-7 (paper), dotted: 1e-8" % end_time, fontsize=10)
    fig.tight_layout()
    save(fig, figures, "peaks_vs_clearance.png")


def acceleration_statistics(study, clearances_mm):
    """Peak, 99.9th percentile and RMS of the slider acceleration, and the energy lost, per run."""
    n = len(clearances_mm)
    grid_max, grid_p999, grid_rms, grid_loss = (np.zeros((n, n)) for _ in range(4))
    for i, cr in enumerate(clearances_mm):
        for j, ca in enumerate(clearances_mm):
            a = study[(cr, ca)]["ax"]
            grid_max[i, j] = np.abs(a).max()
            grid_p999[i, j] = np.percentile(np.abs(a), 99.9)
            grid_rms[i, j] = np.sqrt(np.mean(a * a))
            grid_loss[i, j] = study[(cr, ca)]["total"][0] - study[(cr, ca)]["total"][-1]
    return grid_max, grid_p999, grid_rms, grid_loss


def count_peaks(run, threshold, t0):
    """Acceleration peaks above `threshold` after t0: local maxima of |a| more than 1 ms apart."""
    t, a = run["time"], np.abs(run["ax"])
    above = np.flatnonzero((a > threshold) & (t > t0))
    if above.size == 0:
        return 0
    return 1 + int(np.count_nonzero(np.diff(t[above]) > 1e-3))


INITIAL_IMPACTS = 0.012  # [s] the planar runs' impacts before continuous contact (fig07_08_initial_impacts)


def local_maxima(acceleration, threshold):
    """Peaks of abs(a) above `threshold`: its local maxima (scipy.signal.find_peaks)."""
    from scipy.signal import find_peaks
    return int(find_peaks(np.abs(acceleration), height=threshold)[0].size)


def draw_all(load, figures, clearances_mm):
    os.makedirs(figures, exist_ok=True)
    summary = {}
    pi, pa, pm = load("planar_ideal"), load("planar_aligned"), load("planar_misaligned")
    w = PLANAR_WINDOW
    slider_kinematics(figures, "fig07.png", "Fig. 7: slider, planar slider-crank, aligned clearance joint "
                      "(t = %g-%g s)" % w, window(pi, *w), window(pa, *w))
    slider_kinematics(figures, "fig08.png", "Fig. 8: slider, planar slider-crank, misaligned clearance "
                      "joint (t = %g-%g s)" % w, window(pi, *w), window(pm, *w))
    phase_portraits(figures, "fig09.png", "Fig. 9: phase portraits, aligned clearance joint (t = %g-%g s)" % w,
                    window(pi, *w), window(pa, *w))
    phase_portraits(figures, "fig10.png", "Fig. 10: phase portraits, misaligned clearance joint "
                    "(t = %g-%g s)" % w, window(pi, *w), window(pm, *w))
    rod_rotation(figures, pa, pm)
    initial_impacts(figures, pi, pa, pm, INITIAL_IMPACTS)

    si, sc = load("spatial_ideal"), load("spatial_clearance")
    spatial_comparison(figures, si, sc)
    journal_trajectories(figures, sc)

    study = {(cr, ca): load("study_cr%g_ca%g" % (cr, ca)) for cr in clearances_mm for ca in clearances_mm}
    radial = [study[(cr, 0.1)] for cr in clearances_mm]
    axial = [study[(0.1, ca)] for ca in clearances_mm]
    radial_labels = ["c$_r$ = %g mm" % cr for cr in clearances_mm]
    axial_labels = ["c$_a$ = %g mm" % ca for ca in clearances_mm]
    sweep_panels(figures, "fig15.png", "Fig. 15: slider acceleration for radial clearances (c$_a$ = 0.1 mm)",
                 radial, radial_labels, "time")
    sweep_panels(figures, "fig16.png", "Fig. 16: slider acceleration for axial clearances (c$_r$ = 0.1 mm)",
                 axial, axial_labels, "time")
    sweep_panels(figures, "fig17.png", "Fig. 17: acceleration against velocity, radial clearances "
                 "(c$_a$ = 0.1 mm)", radial, radial_labels, "phase")
    sweep_panels(figures, "fig18.png", "Fig. 18: acceleration against velocity, axial clearances "
                 "(c$_r$ = 0.1 mm)", axial, axial_labels, "phase")
    grid_max, grid_p999, grid_rms, grid_loss = acceleration_statistics(study, clearances_mm)
    fine = {(cr, ca): load("study_tol1e-8_cr%g_ca%g" % (cr, ca)) for cr in clearances_mm for ca in clearances_mm}
    fine_max, fine_p999, fine_rms, fine_loss = acceleration_statistics(fine, clearances_mm)
    peak_surface(figures, "fig19.png", "Fig. 19: peak slider acceleration against radial and axial "
                 "clearance", np.array(clearances_mm), grid_max)
    peak_surface(figures, "fig19_tolerance_1e-8.png", "Fig. 19 at integration tolerance 1e-8 "
                 "(robustness check)", np.array(clearances_mm), fine_max)
    peaks_against_clearance(figures, np.array(clearances_mm),
                            [(grid_max, grid_p999, grid_rms), (fine_max, fine_p999, fine_rms)], (1e-7, 1e-8),
                            float(study[(0.1, 0.1)]["time"][-1]))

    def scenarios(run):
        codes, counts = np.unique(run["joint_scenario"].astype(int), return_counts=True)
        return {runplot.scenario_name(c): int(k) for c, k in zip(codes, counts)}

    late = lambda run: window(run, 0.2, 1.0)  # noqa: E731 (after the initial impacts)
    summary["clearances_mm"] = list(clearances_mm)
    summary["study_rows"] = "radial clearance (rows) x axial clearance (columns)"
    summary["study_peak_acceleration"] = grid_max.tolist()
    summary["study_p999_acceleration"] = grid_p999.tolist()
    summary["study_rms_acceleration"] = grid_rms.tolist()
    summary["study_energy_loss_J"] = grid_loss.tolist()
    summary["study_tolerance_1e-8_peak_acceleration"] = fine_max.tolist()
    summary["study_tolerance_1e-8_p999_acceleration"] = fine_p999.tolist()
    summary["study_tolerance_1e-8_rms_acceleration"] = fine_rms.tolist()
    summary["study_tolerance_1e-8_energy_loss_J"] = fine_loss.tolist()
    summary["planar"] = {
        name: {"peak_acceleration": float(np.abs(run["ax"]).max()),
               "peak_acceleration_after_0.2s": float(np.abs(late(run)["ax"]).max()),
               "peaks_above_10000_after_0.2s": count_peaks(run, 1e4, 0.2),
               "energy_start": float(run["total"][0]), "energy_end": float(run["total"][-1]),
               "rod_e2_max_abs": float(np.abs(run["rod_e2"]).max()),
               "rod_e1_max_abs": float(np.abs(run["rod_e1"]).max()),
               "scenario_report_counts": scenarios(run) if "joint_scenario" in run else {}}
        for name, run in (("ideal", pi), ("aligned", pa), ("misaligned", pm))}
    for t in (0.0, 0.05, 0.1, 0.2, 0.5, 1.0):
        k = min(np.searchsorted(pm["time"], t), len(pm["time"]) - 1)
        summary["planar"]["misaligned"]["axis_angle_deg_at_%gs" % t] = float(np.degrees(pm["joint_axis_angle"][k]))
        summary["planar"]["misaligned"]["rod_e2_at_%gs" % t] = float(pm["rod_e2"][k])
    for name, run in (("aligned", pa), ("misaligned", pm)):
        tail = window(run, 0.5, 1.0)
        ideal_tail = window(pi, 0.5, 1.0)
        summary["planar"][name]["slider_x_rms_difference_to_ideal_0.5_1s"] = float(
            np.sqrt(np.mean((tail["x"] - ideal_tail["x"]) ** 2)))
    for name, run in (("aligned", pa), ("misaligned", pm)):
        free_reports, flight_count, last_free = flights(run["time"], run["joint_scenario"].astype(int))
        first = window(run, 0.0, INITIAL_IMPACTS)
        summary["planar"][name].update({
            "free_flight_reports": free_reports, "flights": flight_count, "last_free_flight_s": last_free,
            "initial_peak_acceleration": float(np.abs(first["ax"]).max()),
            "initial_peaks_above_10000": local_maxima(first["ax"], 1e4),
            "initial_peaks_above_20000": local_maxima(first["ax"], 2e4),
            "axis_angle_deg_max_after_0.2s": float(np.degrees(np.abs(late(run)["joint_axis_angle"]).max()))})
    a_tail, m_tail = window(pa, 0.5, 1.0), window(pm, 0.5, 1.0)
    summary["planar"]["aligned_vs_misaligned_slider_x_rms_difference_0.5_1s"] = float(
        np.sqrt(np.mean((a_tail["x"] - m_tail["x"]) ** 2)))
    summary["spatial"] = {
        name: {"peak_acceleration": float(np.abs(run["ax"]).max()),
               "energy_start": float(run["total"][0]), "energy_end": float(run["total"][-1]),
               "slider_x_range": [float(run["x"].min()), float(run["x"].max())],
               "slider_x_range_last_0.2s": [float(window(run, 0.8, 1.0)["x"].min()),
                                            float(window(run, 0.8, 1.0)["x"].max())],
               "scenario_report_counts": scenarios(run) if "joint_scenario" in run else {}}
        for name, run in (("ideal", si), ("clearance", sc))}
    summary["spatial"]["clearance"]["windows"] = energy_windows(sc)
    summary["tolerance_robustness"] = tolerance_robustness(clearances_mm, grid_max, fine_max, grid_loss, fine_loss)
    return summary


def energy_windows(run, width=0.1):
    """Fig. 13(d): mechanical energy lost, peak |a| and share of report times in contact, per window."""
    rows = []
    for k in range(int(round(run["time"][-1] / width))):
        part = window(run, k * width, (k + 1) * width)
        rows.append({"start_s": k * width, "end_s": (k + 1) * width,
                     "energy_loss_J": float(part["total"][0] - part["total"][-1]),
                     "peak_acceleration": float(np.abs(part["ax"]).max()),
                     "contact_share": float(np.mean(part["joint_scenario"] != 0))})
    return rows


def tolerance_robustness(clearances_mm, peak, fine_peak, loss, fine_loss):
    """How much the 16 runs of the clearance study change from tolerance 1e-7 to 1e-8."""
    change = np.abs(fine_loss / loss - 1.0)
    ratio = fine_peak / peak
    worst = np.unravel_index(np.argmax(change), change.shape)
    return {"energy_loss_relative_change_median": float(np.median(change)),
            "energy_loss_relative_change_max": float(change.max()),
            "energy_loss_largest_change_at_mm": [clearances_mm[worst[0]], clearances_mm[worst[1]]],
            "peak_ratio_range": [float(ratio.min()), float(ratio.max())]}
