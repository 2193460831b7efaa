# SPDX-License-Identifier: BSD-3-Clause
"""Ensemble statistics of one point and the rank test between two points.

The motion after the first impacts is chaotic, so one run's statistic is a draw; the members of a
point give its median and spread, and neighbouring points are compared by ranks (Mann-Whitney),
which assumes nothing about the draws' distribution.
"""
import itertools

import numpy as np
import scipy.stats


def point_statistics(values):
    v = np.asarray(values, dtype=float)
    q1, median, q3 = np.percentile(v, [25, 50, 75])
    return {"n": int(v.size), "median": float(median), "min": float(v.min()), "max": float(v.max()),
            "q1": float(q1), "q3": float(q3)}


def probability_greater(lower, upper):
    """Share of the pairs (x from `lower`, y from `upper`) with y > x, ties counting half: the
    Mann-Whitney U statistic over the number of pairs. 0.5 means no trend; 1 means every member of
    `upper` is above every member of `lower`."""
    x, y = np.asarray(lower, float)[:, None], np.asarray(upper, float)[None, :]
    return float(np.mean((y > x) + 0.5 * (y == x)))


def _rank_sum_of_second(first, second, axis):
    pooled = np.concatenate([first, second], axis=axis)
    ranks = scipy.stats.rankdata(pooled, axis=axis)  # ties share their mean rank
    return np.take(ranks, np.arange(first.shape[axis], pooled.shape[axis]), axis=axis).sum(axis=axis)


def _p_value_by_enumeration(lower, upper):
    """The share of the splits of the pooled values into groups of the two sizes whose second
    group's rank sum is at least the observed one. For the small samples scipy's
    permutation_test refuses (fewer than two values in a group)."""
    pooled = np.concatenate([lower, upper])
    ranks = scipy.stats.rankdata(pooled)  # ties share their mean rank
    observed = ranks[lower.size:].sum()
    sums = [ranks[list(second)].sum() for second in itertools.combinations(range(pooled.size), upper.size)]
    # A relative margin, as scipy's permutation_test uses, so that equal sums count as equal.
    return float(np.mean(np.asarray(sums) >= observed * (1.0 - 1e-14)))


def p_value_greater(lower, upper):
    """One-sided exact p-value of the Mann-Whitney test that `upper` tends to be greater than
    `lower`. Without ties, scipy's exact null distribution; with ties (two members with the same
    value) that distribution is not exact, so the rank sum is compared with every split of the
    pooled values instead (scipy.stats.permutation_test, all splits enumerated: slower, seconds
    for 9 + 9 members; enumerated here when a point has a single member, which scipy refuses)."""
    lower, upper = np.asarray(lower, float), np.asarray(upper, float)
    if lower.size == 0 or upper.size == 0:
        raise ValueError("p_value_greater: both samples need a value (sizes %d, %d)" % (lower.size, upper.size))
    if np.unique(np.concatenate([lower, upper])).size == lower.size + upper.size:
        return float(scipy.stats.mannwhitneyu(upper, lower, alternative="greater", method="exact").pvalue)
    if min(lower.size, upper.size) < 2:
        return _p_value_by_enumeration(lower, upper)
    result = scipy.stats.permutation_test((lower, upper), _rank_sum_of_second, permutation_type="independent",
                                          vectorized=True, n_resamples=np.inf, alternative="greater")
    return float(result.pvalue)
