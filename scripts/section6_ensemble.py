# SPDX-License-Identifier: BSD-3-Clause
"""The clearance trend of Sec. 6.2 ("the increase of clearance is typically associated with the
increase of magnitude of the acceleration peaks") as a statistical statement over ensembles of
runs, drawn from the reduced runs of reproduce_section6.py.

Each study point has an ensemble of runs that differ only by the initial crank speed scaled by
1 + k 1e-9 (reproduce_section6.ENSEMBLE_OFFSETS). The motion after the first impacts is chaotic, so
the members make different impacts; their spread is the scatter of a single run's statistic, and
the median is the figure to compare across clearances.
"""
import functools
import itertools
import os

import numpy as np

from section6_figures import plt, save  # Agg backend set there

# Statistics that leave out the first impacts start here [s]: the journal starts centred and meets
# the wall within the first 10 ms (Fig. 14); 50 ms keeps the initial transient out of them.
POST_IMPACT_START = 0.05
STATISTICS = (
    ("peak", "peak |a| over 1 s"),
    ("p999", "99.9th percentile of |a|, t > %g s" % POST_IMPACT_START),
    ("p99", "99th percentile of |a|, t > %g s" % POST_IMPACT_START),
    ("rms", "RMS of a, t > %g s" % POST_IMPACT_START),
)


def member_statistics(run):
    """One run's slider-acceleration statistics [m/s^2] and its energy loss over the run [J]."""
    a = run["ax"]
    late = np.abs(a[run["time"] > POST_IMPACT_START])
    return {"peak": float(np.abs(a).max()),
            "p999": float(np.percentile(late, 99.9)),
            "p99": float(np.percentile(late, 99.0)),
            "rms": float(np.sqrt(np.mean(late * late))),
            "energy_loss": float(run["total"][0] - run["total"][-1])}


def probability_greater(lower, upper):
    """Share of the pairs (x from `lower`, y from `upper`) with y > x, ties counting half: the
    Mann-Whitney U statistic divided by the number of pairs. 0.5 means no trend; 1 means every
    member of `upper` is above every member of `lower`."""
    x, y = np.asarray(lower)[:, None], np.asarray(upper)[None, :]
    return float(np.mean((y > x) + 0.5 * (y == x)))


@functools.lru_cache(maxsize=None)
def _splits(total, size):
    """Every choice of `size` indices out of `total`, one per row (48 620 rows for 9 + 9)."""
    return np.array(list(itertools.combinations(range(total), size)), dtype=np.int64)


def p_value_greater(lower, upper):
    """One-sided exact permutation p-value of the Mann-Whitney test that `upper` tends to be
    greater than `lower`: the share of all ways of splitting the pooled values into groups of
    these sizes whose rank sum for the second group is at least the observed one. Computed by
    enumeration rather than with scipy.stats.mannwhitneyu because scipy is not among the project's
    Debian packages; the ensembles are small (9 + 9 values: 48 620 splits)."""
    pooled = np.concatenate([np.asarray(lower, float), np.asarray(upper, float)])
    order = pooled.argsort(kind="stable")
    ranks = np.empty(len(pooled))
    ranks[order] = np.arange(1, len(pooled) + 1)
    for value in np.unique(pooled):  # ties share their mean rank
        tied = pooled == value
        ranks[tied] = ranks[tied].mean()
    observed = ranks[len(lower):].sum()
    sums = ranks[_splits(len(pooled), len(upper))].sum(axis=1)
    return float(np.mean(sums >= observed - 1e-9))  # 1e-9: rank sums are multiples of 0.5


def sweeps(clearances_mm):
    """The three sweeps of the study: name -> list of (radial, axial) points [mm], and a label."""
    return {"radial": ([(c, 0.1) for c in clearances_mm], "c$_r$ varied, c$_a$ = 0.1 mm"),
            "axial": ([(0.1, c) for c in clearances_mm], "c$_a$ varied, c$_r$ = 0.1 mm"),
            "diagonal": ([(c, c) for c in clearances_mm], "c$_r$ = c$_a$ varied")}


def sweep_summary(members, points, clearances_mm):
    """Medians, minima, maxima per clearance and the pairwise trend probabilities of one sweep."""
    out = {}
    for stat in [s for s, _ in STATISTICS] + ["energy_loss"]:
        values = [np.array([m[stat] for m in members[p]]) for p in points]
        medians = [float(np.median(v)) for v in values]
        out[stat] = {
            "median": medians, "min": [float(v.min()) for v in values], "max": [float(v.max()) for v in values],
            "medians_increase_monotonically": bool(all(b > a for a, b in zip(medians, medians[1:]))),
            "probability_next_clearance_greater": [probability_greater(a, b) for a, b in zip(values, values[1:])],
            "probability_largest_greater_than_smallest": probability_greater(values[0], values[-1]),
            "p_value_next_clearance_greater": [p_value_greater(a, b) for a, b in zip(values, values[1:])],
            "p_value_largest_greater_than_smallest": p_value_greater(values[0], values[-1]),
        }
    out["clearances_mm"] = list(clearances_mm)
    return out


def trend_figure(figures, clearances_mm, members, sweep_table, name, settings):
    """Median with min-max bars against clearance, per statistic and sweep; members as dots."""
    fig, axes = plt.subplots(2, 2, figsize=(12, 8.5))
    colours = {"radial": "tab:blue", "axial": "tab:orange", "diagonal": "tab:green"}
    shift = {"radial": -0.008, "axial": 0.0, "diagonal": 0.008}  # mm, keeps the bars apart
    c = np.array(clearances_mm)
    for ax, (stat, label) in zip(axes.flat, STATISTICS):
        for sweep, (points, sweep_label) in sweep_table.items():
            values = [np.array([m[stat] for m in members[p]]) for p in points]
            med = np.array([np.median(v) for v in values])
            low = med - np.array([v.min() for v in values])
            high = np.array([v.max() for v in values]) - med
            x = c + shift[sweep]
            ax.errorbar(x, med, yerr=[low, high], color=colours[sweep], marker="o", capsize=3,
                        linewidth=1.2, label=sweep_label + " (median, min-max)")
            for xi, v in zip(x, values):
                ax.plot(np.full(len(v), xi), v, ".", color=colours[sweep], markersize=3, alpha=0.5)
        ax.set_xlabel("clearance [mm]")
        ax.set_ylabel(label + " [m/s$^2$]")
        ax.grid(alpha=0.3)
    axes.flat[0].legend(fontsize=7)
    n = len(next(iter(members.values())))
    fig.suptitle("Slider acceleration against clearance, spatial slider-crank: ensembles of %d runs per "
                 "point (initial crank speed x (1 + k 1e-9)), %s" % (n, settings), fontsize=10)
    fig.tight_layout()
    save(fig, figures, name)


def draw(load, figures, clearances_mm, points, offsets, run_name, figure_name, settings):
    """Loads every ensemble member, draws FIGURES/figure_name for the sweeps whose points all have
    an ensemble (`settings` names the integration settings in its title) and returns the summary."""
    os.makedirs(figures, exist_ok=True)
    members = {p: [member_statistics(load(run_name(p[0], p[1], k))) for k in offsets] for p in points}
    sweep_table = {name: sweep for name, sweep in sweeps(clearances_mm).items()
                   if all(p in members for p in sweep[0])}
    trend_figure(figures, clearances_mm, members, sweep_table, figure_name, settings)
    return {"offsets": list(offsets),
            "post_impact_start_s": POST_IMPACT_START,
            "members": {"cr%g_ca%g" % p: members[p] for p in points},
            "sweeps": {name: sweep_summary(members, pts, clearances_mm)
                       for name, (pts, _) in sweep_table.items()}}
