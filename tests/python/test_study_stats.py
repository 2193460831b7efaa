# SPDX-License-Identifier: BSD-3-Clause
"""The rank test between two points of a study (clearjoint.study.stats), including points of a
single member, whose ties scipy's permutation test refuses."""
import numpy as np
import pytest
import scipy.stats

from clearjoint.study import stats


def test_two_single_member_points_with_the_same_value_show_no_trend():
    assert stats.probability_greater([9.2], [9.2]) == 0.5
    assert stats.p_value_greater([9.2], [9.2]) == 1.0


def test_two_single_member_points_with_different_values_have_p_value_one_half():
    assert stats.p_value_greater([1.0], [2.0]) == 0.5
    assert stats.p_value_greater([2.0], [1.0]) == 1.0


def test_a_single_member_tied_with_a_larger_point_counts_every_split():
    # Pooled ranks 1.5, 1.5, 3: the upper pair's rank sum 4.5 is reached by 2 of the 3 splits.
    assert stats.p_value_greater([1.0], [1.0, 2.0]) == pytest.approx(2.0 / 3.0)


@pytest.mark.parametrize("lower, upper", [([1.0, 2.0, 2.0, 3.0], [2.0, 3.0, 3.0, 4.0]),
                                          ([1.0, 2.0, 2.0, 3.0, 5.0], [2.0, 3.0, 3.0, 4.0, 6.0, 7.0])])
def test_enumerating_the_splits_agrees_with_scipys_permutation_test_on_tied_samples(lower, upper):
    lower, upper = np.asarray(lower), np.asarray(upper)
    by_scipy = scipy.stats.permutation_test((lower, upper), stats._rank_sum_of_second,
                                            permutation_type="independent", vectorized=True,
                                            n_resamples=np.inf, alternative="greater").pvalue
    assert stats._p_value_by_enumeration(lower, upper) == pytest.approx(by_scipy, rel=1e-12)


def test_an_empty_sample_is_an_error_naming_the_sizes():
    with pytest.raises(ValueError, match="sizes 0, 2"):
        stats.p_value_greater([], [1.0, 2.0])
