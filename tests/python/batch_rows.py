# SPDX-License-Identifier: BSD-3-Clause
"""Bit-for-bit comparisons of packed batch answers (DetectionBatch, PinInHoleBatch) with single
calls' answers, shared by the detect tests of both joints."""
import struct

import numpy as np


def bits(x):
    """The double's eight bytes: equal bits, not equal values (NaN equals NaN, -0 differs from 0)."""
    return struct.pack("<d", float(x))


def same_vector(a, b):
    return [bits(x) for x in a] == [bits(x) for x in b]


def assert_row_equals_single(batch, n, single):
    """Row n of a batch holds exactly the single-pose answer, bit for bit."""
    assert batch.scenario[n] == int(single.scenario)
    assert batch.aligned[n] == single.aligned
    assert batch.certificate[n] == int(single.certificate.level)
    assert batch.certificate_reason[n] == int(single.certificate.reason)
    assert batch.contact_count[n] == single.contact_count
    rows = range(batch.contact_start[n], batch.contact_start[n + 1])
    assert len(rows) == single.contact_count
    for k, contact in zip(rows, single.contacts):
        assert batch.contact_pose[k] == n
        assert batch.contact_type[k] == int(contact.type)
        assert batch.contact_base[k] == int(contact.base)
        assert bits(batch.depth[k]) == bits(contact.depth)
        assert bits(batch.depth_error[k]) == bits(contact.depth_error)
        assert bits(batch.point_journal_error[k]) == bits(contact.point_journal_error)
        assert bits(batch.point_bearing_error[k]) == bits(contact.point_bearing_error)
        assert same_vector(batch.point_journal[k], contact.point_journal)
        assert same_vector(batch.point_bearing[k], contact.point_bearing)
        assert same_vector(batch.normal[k], contact.normal)
        assert batch.contact_certificate[k] == int(contact.certificate.level)
        assert batch.contact_certificate_reason[k] == int(contact.certificate.reason)
        assert batch.crossing_count[k] == len(contact.crossings)
        for x, crossing in enumerate(contact.crossings):
            assert bits(batch.crossing_angle[k, x]) == bits(crossing.angle)
            assert bits(batch.crossing_angle_error[k, x]) == bits(crossing.angle_error)
            assert same_vector(batch.crossing_point[k, x], crossing.point)
            assert bits(batch.crossing_point_error[k, x]) == bits(crossing.point_error)
            assert batch.crossing_multiplicity[k, x] == crossing.multiplicity
        for x in range(len(contact.crossings), 2):
            assert np.isnan(batch.crossing_angle[k, x]) and batch.crossing_multiplicity[k, x] == 0
