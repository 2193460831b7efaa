# SPDX-License-Identifier: BSD-3-Clause
"""The tables of docs/reports/reproduction.md, generated from the Section 6 study stores: each sits
between `<!-- generated: NAME -->` and `<!-- end generated: NAME -->` and is replaced whole."""
import os
import re

import numpy as np

TOLERANCES = (1e-7, 1e-8)
STATISTIC_NAMES = {"peak": "peak", "p999": "99.9th percentile", "p99": "99th percentile", "rms": "RMS"}


def _number(value):
    """Three significant figures at most, as the page writes accelerations: 575, 15.7."""
    return "%.0f" % value if abs(value) >= 100 else "%.1f" % value


def _tolerance(value):
    return ("%g" % value).replace("e-0", "e-")


def _p_value(p):
    if p < 1e-4:
        return "< 1e-4"
    if p < 1e-3:
        return ("%.1e" % p).replace("e-0", "e-")
    return "%.2g" % p if p < 0.1 else "%.2f" % p


def single_run_peaks(load, clearances_mm):
    """Figs. 15, 16 and the diagonal of Fig. 19: the peak |a| of single runs at both tolerances."""
    sweeps = (("c_r varied, c_a = 0.1 mm", lambda c: (c, 0.1)), ("c_a varied, c_r = 0.1 mm", lambda c: (0.1, c)),
              ("c_r = c_a varied", lambda c: (c, c)))
    lines = ["| | %s |" % " | ".join("%g mm" % c for c in clearances_mm),
             "| --- |%s" % (" ---: |" * len(clearances_mm))]
    for label, point in sweeps:
        for tolerance in TOLERANCES:
            prefix = "study_" if tolerance == TOLERANCES[0] else "study_tol1e-8_"
            peaks = [np.abs(load("%scr%g_ca%g" % ((prefix,) + point(c)))["ax"]).max() for c in clearances_mm]
            name = ("%s, tolerance %s" % (label, _tolerance(tolerance)) if tolerance == TOLERANCES[0]
                    else "same at tolerance %s" % _tolerance(tolerance))
            lines.append("| %s | %s |" % (name, " | ".join("%.0f" % p for p in peaks)))
    return "\n".join(lines)


def ensemble_table(summary, study, designs, statistics, clearances_mm):
    """Median (min-max) per point along each design, P (p) between neighbours and first-last."""
    steps = ", ".join("%g->%g" % pair for pair in zip(clearances_mm, clearances_mm[1:]))
    lines = ["| statistic | sweep | %s | P (p) %s | P (p) %g->%g |" % (
                 " | ".join("%g mm" % c for c in clearances_mm), steps, clearances_mm[0], clearances_mm[-1]),
             "| --- | --- |%s --- | --- |" % (" ---: |" * len(clearances_mm))]
    rows = {(r["point_id"]): r for r in summary["runs"]}
    for statistic in statistics:
        for name in designs:
            design = study.design(name)
            line = sorted((pid for pid, row in rows.items() if name in row["designs"].split(" ")),
                          key=lambda pid: rows[pid][design["x"]])
            cells = []
            for pid in line:
                e = summary["points"][pid][statistic]
                cells.append("%s (%s-%s)" % (_number(e["median"]), _number(e["min"]), _number(e["max"])))
            trends = [t for t in summary["trends"] if t["design"] == name and t["statistic"] == statistic]
            cell = lambda t: "%.2f (%s)" % (t["probability_greater"], _p_value(t["p_value_greater"]))  # noqa: E731
            neighbours = ", ".join(cell(t) for t in trends[:-1])
            label = design.get("label", name).replace("$", "")
            lines.append("| %s | %s | %s | %s | %s |" % (STATISTIC_NAMES.get(statistic, statistic), label,
                                                        " | ".join(cells), neighbours, cell(trends[-1])))
    return "\n".join(lines)


def _table(header, rows):
    lines = ["| %s |" % " | ".join(header), "|%s" % "".join(" --- |" if k == 0 else " ---: |" for k in range(len(header)))]
    lines += ["| %s |" % " | ".join(str(cell) for cell in row) for row in rows]
    return "\n".join(lines)


def _scenarios(counts):
    return ", ".join("%s %d" % (name, count) for name, count in counts.items())


def _ms(seconds):
    return "%.2f ms" % (1e3 * seconds) if seconds == seconds else "never"


def planar_runs(summary):
    """Sec. 6.1: the planar runs' energy, initial impacts, free flight and scenarios."""
    planar = summary["planar"]
    runs = ("aligned", "misaligned")
    rows = [("mechanical energy at 0 s, after 1 s [J] (ideal: %.2f, %.2f)" % (
                planar["ideal"]["energy_start"], planar["ideal"]["energy_end"]),)
            + tuple("%.2f, %.2f" % (planar[r]["energy_start"], planar[r]["energy_end"]) for r in runs),
            ("largest abs(a) in the first 12 ms [m/s^2] (ideal: %.0f over 1 s)" % planar["ideal"]["peak_acceleration"],)
            + tuple("%.0f" % planar[r]["initial_peak_acceleration"] for r in runs),
            ("local maxima of abs(a) above 1e4, 2e4 m/s^2 in the first 12 ms",)
            + tuple("%d, %d" % (planar[r]["initial_peaks_above_10000"], planar[r]["initial_peaks_above_20000"])
                    for r in runs),
            ("report times in free flight after the first contact (flights); the last",)
            + tuple("%d (%d); %s" % (planar[r]["free_flight_reports"], planar[r]["flights"],
                                     _ms(planar[r]["last_free_flight_s"])) for r in runs),
            ("largest abs(a) after 0.2 s [m/s^2]",)
            + tuple("%.0f" % planar[r]["peak_acceleration_after_0.2s"] for r in runs),
            ("slider position, RMS difference to the ideal mechanism over 0.5-1 s [mm]",)
            + tuple("%.0f" % (1e3 * planar[r]["slider_x_rms_difference_to_ideal_0.5_1s"]) for r in runs),
            ("slider position, RMS difference aligned - misaligned over 0.5-1 s [mm]",
             "%.2f" % (1e3 * planar["aligned_vs_misaligned_slider_x_rms_difference_0.5_1s"]), ""),
            ("largest abs(e1), abs(e2) of the rod",)
            + tuple("%.3g, %.3g" % (planar[r]["rod_e1_max_abs"], planar[r]["rod_e2_max_abs"]) for r in runs),
            ("report times per contact scenario (Fig. 2)",)
            + tuple(_scenarios(planar[r]["scenario_report_counts"]) for r in runs)]
    return _table(("", "aligned", "misaligned"), rows)


def misaligned_tilt(summary):
    """Fig. 11: the misaligned rod's e2 and the journal-bearing angle at a few times."""
    run = summary["planar"]["misaligned"]
    rows = [("%g" % t, "%.3g" % run["rod_e2_at_%gs" % t], "%.3g" % run["axis_angle_deg_at_%gs" % t])
            for t in (0.0, 0.05, 0.1, 0.2, 0.5, 1.0)]
    rows.append(("largest after 0.2 s", "", "%.3g" % run["axis_angle_deg_max_after_0.2s"]))
    return _table(("t [s]", "rod e2", "journal-bearing angle [deg]"), rows)


def _settling_scale(name, run):
    """(1 - ce) times the settling time: constant if it grows like 1/(1 - ce), as a bouncing ball's."""
    if not name.startswith("no friction, ce ") or float(name.split()[-1]) >= 1.0:
        return ""
    return _ms((1.0 - float(name.split()[-1])) * run["last_free_flight_s"])


def settling(summary):
    """Why the planar journal settles on the wall: the variants of reproduction/studies/section6_settling.json."""
    force = summary["settling"]["planar_contact_force_N"]
    lines = ["Contact force on the journal in the plane of motion after 0.05 s, Table 2 with friction: "
             "%.0f N to %.0f N (median %.0f N)." % (force[0], force[2], force[1]), ""]
    rows = []
    for name, run in summary["settling"]["planar"].items():
        depth = run["line_depth_after_0.05s_m"]
        rows.append((name, "%.3g" % run["energy_loss_J"], "%d" % run["free_flight_reports"], "%d" % run["flights"],
                     _ms(run["last_free_flight_s"]), _settling_scale(name, run),
                     "%.2g-%.2g" % (1e6 * depth[0], 1e6 * depth[1]) if depth else "no line contact"))
    lines.append(_table(("planar aligned clearance joint", "energy lost in 1 s [J]",
                         "report times in free flight", "flights", "last free flight",
                         "(1 - ce) x last free flight",
                         "line-contact depth after 0.05 s [µm]"), rows))
    return "\n".join(lines)


def spatial_runs(summary):
    spatial = summary["spatial"]
    rows = [("peak abs(a) of the slider [m/s^2]",) + tuple("%.0f" % spatial[r]["peak_acceleration"]
                                                           for r in ("ideal", "clearance")),
            ("mechanical energy at 0 s, after 1 s [J]",) + tuple(
                "%.3f, %.3f" % (spatial[r]["energy_start"], spatial[r]["energy_end"]) for r in ("ideal", "clearance")),
            ("slider position range over 1 s, over the last 0.2 s [m]",) + tuple(
                "%.3f-%.3f, %.3f-%.3f" % tuple(spatial[r]["slider_x_range"] + spatial[r]["slider_x_range_last_0.2s"])
                for r in ("ideal", "clearance")),
            ("report times per contact scenario (Fig. 2)", "",
             _scenarios(spatial["clearance"]["scenario_report_counts"]))]
    lines = [_table(("", "ideal joints", "clearance joint (Table 2)"), rows), "",
             "Per 0.1 s of the clearance run: mechanical energy lost, peak abs(a) of the slider, share of "
             "report times with a contact.", ""]
    lines.append(_table(("t [s]", "energy lost [J]", "peak abs(a) [m/s^2]", "in contact"), [
        ("%.1f-%.1f" % (w["start_s"], w["end_s"]), "%.3f" % w["energy_loss_J"], "%.0f" % w["peak_acceleration"],
         "%.0f %%" % (100 * w["contact_share"])) for w in spatial["clearance"]["windows"]]))
    return "\n".join(lines)


def spatial_friction(summary):
    """Where the spatial mechanism's energy goes: with and without friction, and the impact-speed floor."""
    s = summary["settling"]
    runs = [("ideal joints", s["spatial_ideal"])]
    floors = s["spatial_impact_speed_floor"]
    runs += [("clearance joint, Table 2 (floor 1e-3 m/s)", floors["0.001"]),
             ("same without friction", s["spatial_frictionless"])]
    runs += [("Table 2, floor %s m/s" % f, floors[f]) for f in sorted(floors, key=float) if f != "0.001"]
    rows = [(name, "%.3f" % r["energy_loss_J"], "%.2f, %.2f" % (r["largest_angle_rad"] / (2 * np.pi), r["turns"]),
             "%.3f s" % r["turns_back_at_s"] if r["turns_back_at_s"] is not None else "never",
             "%.1f, %.1f" % (r["normal_force_sum_mean_N"], r["net_force_mean_N"]) if "net_force_mean_N" in r else "",
             "%.0f" % r["peak_acceleration"]) for name, r in runs]
    return _table(("spatial slider-crank", "energy lost in 1 s [J]", "crank angle: largest, at 1 s [turns]",
                   "crank turns back at", "until then, mean contact forces: sum of normal forces, net [N]",
                   "peak abs(a) [m/s^2]"), rows)


def tolerance_robustness(summary):
    r = summary["tolerance_robustness"]
    return _table(("the 16 runs of the clearance study, tolerance 1e-7 against 1e-8", "value"), [
        ("energy lost in 1 s, relative change: median", "%.1f %%" % (100 * r["energy_loss_relative_change_median"])),
        ("energy lost in 1 s, relative change: largest (at c_r, c_a = %g, %g mm)" % tuple(
            r["energy_loss_largest_change_at_mm"]), "%.0f %%" % (100 * r["energy_loss_relative_change_max"])),
        ("peak abs(a) at 1e-8 / at 1e-7: smallest, largest", "%.2f, %.2f" % tuple(r["peak_ratio_range"]))])


def provenance(summary, runs):
    import subprocess
    import time
    try:
        commit = subprocess.run(["git", "rev-parse", "--short=10", "HEAD"], capture_output=True, text=True,
                                check=True).stdout.strip()
        if subprocess.run(["git", "status", "--porcelain", "--untracked-files=no", "--", "geometry", "dynamics",
                           "apps", "bindings"], capture_output=True, text=True, check=True).stdout.strip():
            commit += " (with uncommitted changes to the library)"
    except (OSError, subprocess.CalledProcessError):
        commit = "unknown"
    wall = sorted(summary["wall_seconds_per_run"])
    load = ", ".join("%.1f" % x for x in os.getloadavg())
    return ("Generated by `reproduction/reproduce_section6.py` from commit %s on %s; %d runs, %.1f-%.1f s "
            "(median %.1f s) each on one of %d cores; load average %s when the page was written." % (
                commit, time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), runs, wall[0], wall[-1],
                float(np.median(wall)), os.cpu_count(), load))


# The generated blocks whose numbers "findings_moved" compares, with where they are on the page.
MOVED_BLOCKS = (("tolerance_robustness", "tolerance 1e-7 against 1e-8"), ("planar_runs", "6.1 planar runs"),
                ("settling", "6.1 settling variants"), ("misaligned_tilt", "Fig. 11 tilt"),
                ("spatial_runs", "Fig. 13 spatial runs"), ("spatial_friction", "Fig. 13 friction"),
                ("single_run_peaks", "Figs. 15, 16, 19 single runs"),
                ("ensembles_tolerance_1e-7", "ensembles, tolerance 1e-7"),
                ("ensembles_tolerance_1e-8", "ensembles, tolerance 1e-8"))
BLOCK_PATTERN = r"<!-- generated: %s -->\n(.*?)\n<!-- end generated: %s -->"


def block(text, name):
    match = re.search(BLOCK_PATTERN % (re.escape(name), re.escape(name)), text, re.S)
    return match.group(1) if match else None


def _rows(body):
    """A block's lines as (key, label, cells): table rows by their table and row number (the
    header and rule skipped), other non-empty lines whole. A row's label is its text columns
    (the statistic and sweep of an ensemble row), its cells the rest."""
    rows, table, row = [], -1, 0
    in_table = False
    for line in body.splitlines():
        if line.startswith("|"):
            if not in_table:
                table, row, in_table, header = table + 1, 0, True, True
                continue
            if header:  # the rule under the header
                header = False
                continue
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            text_columns = 2 if cells[0] in STATISTIC_NAMES.values() else 1
            rows.append(((table, row), ", ".join(cells[:text_columns]), cells[text_columns:]))
            row += 1
        else:
            in_table = False
            if line.strip():
                rows.append((("text", len(rows)), "", [line.strip()]))
    return rows


def findings_moved(previous, page_now):
    """The rows of the generated tables whose numbers differ between the previous page and this
    one, as a table (None when nothing moved): where, the row, its cells before and now."""
    moved = []
    for name, where in MOVED_BLOCKS:
        before, now = block(previous, name), block(page_now, name)
        if before is None or now is None:
            continue
        old_rows = {key: (label, cells) for key, label, cells in _rows(before)}
        for key, label, cells in _rows(now):
            old_label, old_cells = old_rows.get(key, (label, []))
            if (old_label, old_cells) == (label, cells):
                continue
            shown_label = label if old_label == label else "%s (before: %s)" % (label, old_label)
            moved.append((where, shown_label or "(text)", "; ".join(old_cells) or "(not on the page)",
                          "; ".join(cells)))
    if not moved:
        return None
    return "\n".join(["| where | row | previous page | this page |", "| --- | --- | --- | --- |"] +
                      ["| %s |" % " | ".join(row) for row in moved])


def _previous_source(previous):
    """'commit ... on DATE' of the previous page's provenance line."""
    match = re.search(r"from commit (.+?) on (\d{4}-\d\d-\d\d)", block(previous, "provenance") or "")
    return "the page generated from commit %s on %s" % match.groups() if match else "the previous page"


def replace_block(text, name, body):
    pattern = re.compile(r"(<!-- generated: %s -->\n).*?(\n<!-- end generated: %s -->)" % (
        re.escape(name), re.escape(name)), re.S)
    if not pattern.search(text):
        raise SystemExit("docs/reports/reproduction.md: no generated block %r" % name)
    return pattern.sub(lambda m: m.group(1) + body + m.group(2), text)


def update_page(page, load, ensembles, study, clearances_mm, summary, runs):
    with open(page) as f:
        text = f.read()
    previous = text
    text = replace_block(text, "provenance", provenance(summary, runs))
    for name, block in (("planar_runs", planar_runs), ("misaligned_tilt", misaligned_tilt), ("settling", settling),
                        ("spatial_runs", spatial_runs), ("spatial_friction", spatial_friction),
                        ("tolerance_robustness", tolerance_robustness)):
        text = replace_block(text, name, block(summary))
    text = replace_block(text, "single_run_peaks", single_run_peaks(load, clearances_mm))
    text = replace_block(text, "ensembles_tolerance_1e-7", ensemble_table(
        ensembles, study, ["radial", "axial", "diagonal"], ["peak", "p999", "rms"], clearances_mm))
    text = replace_block(text, "ensembles_tolerance_1e-8", ensemble_table(
        ensembles, study, ["radial_tolerance_1e-8", "axial_tolerance_1e-8"], ["peak", "p999", "rms"], clearances_mm))
    # Which numbers moved relative to the page as it stood before this run.
    moved, source = findings_moved(previous, text), _previous_source(previous)
    text = replace_block(text, "findings_moved", (
        "Rows of the tables above that changed, relative to %s (cells in the order of their table's "
        "columns):\n\n%s" % (source, moved)) if moved is not None else (
        "No number in the tables above moved relative to %s: every row of every generated table is the "
        "same, to the digits printed." % source))
    with open(page + ".partial", "w") as f:
        f.write(text)
    os.replace(page + ".partial", page)
