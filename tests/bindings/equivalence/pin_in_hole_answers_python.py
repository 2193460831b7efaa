# SPDX-License-Identifier: BSD-3-Clause
"""Python's answers for the pin-in-hole equivalence test (README.md), compared with the C++
reference line by line: clearjoint.detect_pin_in_hole on each test case record (one call), and on
the random poses as one NumPy batch, the packed arrays of a PinInHoleBatch written as the lines.

Python names a bad input after its own arguments ("PinInHoleDimensions.pin_radius = ...", not
"dimensions.pin_radius = ..."), so a test case the reference answers with an error must raise
ValueError here; every other line must equal the reference's byte for byte.

usage: pin_in_hole_answers_python.py INPUT REFERENCE
"""
import struct
import sys

import numpy as np

import clearjoint

RECORD = 23


def hex_bits(x):
    return "%016X" % struct.unpack("<Q", struct.pack("<d", float(x)))[0]


def vector(v):
    return " ".join(hex_bits(x) for x in v)


def text(reason):
    return '"%s"' % clearjoint.certificate_reason_text(int(reason))


def contact_text(c):
    """README.md's contact, from a dict with the packed arrays' names and one row's values."""
    parts = ["|", str(c["type"]), str(c["base"]), hex_bits(c["depth"]), vector(c["point_journal"]),
             vector(c["point_bearing"]), vector(c["normal"]), hex_bits(c["depth_error"]),
             hex_bits(c["point_journal_error"]), hex_bits(c["point_bearing_error"]),
             str(c["crossing_count"])]
    for x in range(c["crossing_count"]):
        parts += [hex_bits(c["crossing_angle"][x]), hex_bits(c["crossing_angle_error"][x]),
                  vector(c["crossing_point"][x]), hex_bits(c["crossing_point_error"][x]),
                  str(c["crossing_multiplicity"][x])]
    parts += [str(c["certificate"]), str(c["certificate_reason"]), text(c["certificate_reason"])]
    return " ".join(parts)


def single_line(index, r):
    """A PinInHoleContacts as README.md's S line."""
    head = "S %d ok %d %d %d %d %s %d" % (index, int(r.scenario), int(r.aligned), int(r.certificate.level),
                                          int(r.certificate.reason), text(r.certificate.reason),
                                          r.contact_count)
    contacts = []
    for c in r.contacts:
        contacts.append(contact_text({
            "type": int(c.type), "base": int(c.base), "depth": c.depth, "point_journal": c.point_journal,
            "point_bearing": c.point_bearing, "normal": c.normal, "depth_error": c.depth_error,
            "point_journal_error": c.point_journal_error, "point_bearing_error": c.point_bearing_error,
            "crossing_count": len(c.crossings),
            "crossing_angle": [x.angle for x in c.crossings],
            "crossing_angle_error": [x.angle_error for x in c.crossings],
            "crossing_point": [x.point for x in c.crossings],
            "crossing_point_error": [x.point_error for x in c.crossings],
            "crossing_multiplicity": [x.multiplicity for x in c.crossings],
            "certificate": int(c.certificate.level), "certificate_reason": int(c.certificate.reason)}))
    return " ".join([head] + contacts)


def batch_lines(first_index, b):
    """The rows of a PinInHoleBatch as S lines, read from its packed arrays."""
    lines = []
    for n in range(len(b)):
        head = "S %d ok %d %d %d %d %s %d" % (first_index + n, b.scenario[n], int(b.aligned[n]), b.certificate[n],
                                              b.certificate_reason[n], text(b.certificate_reason[n]),
                                              b.contact_count[n])
        contacts = []
        for k in range(b.contact_start[n], b.contact_start[n + 1]):
            contacts.append(contact_text({
                "type": b.contact_type[k], "base": b.contact_base[k], "depth": b.depth[k],
                "point_journal": b.point_journal[k], "point_bearing": b.point_bearing[k], "normal": b.normal[k],
                "depth_error": b.depth_error[k], "point_journal_error": b.point_journal_error[k],
                "point_bearing_error": b.point_bearing_error[k], "crossing_count": int(b.crossing_count[k]),
                "crossing_angle": b.crossing_angle[k], "crossing_angle_error": b.crossing_angle_error[k],
                "crossing_point": b.crossing_point[k], "crossing_point_error": b.crossing_point_error[k],
                "crossing_multiplicity": b.crossing_multiplicity[k],
                "certificate": b.contact_certificate[k], "certificate_reason": b.contact_certificate_reason[k]}))
        lines.append(" ".join([head] + contacts))
    return lines


def dimensions(r):
    stops = tuple((r[4 + 2 * k], r[5 + 2 * k]) for k in range(int(r[3])))
    return clearjoint.PinInHoleDimensions(hole_radius=r[0], hole_length=r[1], pin_radius=r[2], stops=stops)


def options(r):
    return {"certify": bool(r[20] != 0.0), "parallel_angle_tolerance": float(r[21]),
            "exact_fallback": bool(r[22] != 0.0)}


def main(input_path, reference_path):
    data = np.fromfile(input_path, dtype=np.float64)
    count, singles = int(data[0]), int(data[1])
    records = data[RECORD:RECORD * (count + 1)].reshape(count, RECORD)
    with open(reference_path) as file:
        reference = file.read().splitlines()
    if len(reference) != count:
        print(f"{reference_path}: {len(reference)} lines for {count} records")
        return 1
    mine = []
    errors = 0
    for i in range(singles):
        r = records[i]
        try:
            answer = clearjoint.detect_pin_in_hole(dimensions(r), r[8:11], r[11:14], r[14:17], r[17:20],
                                                   **options(r))
            mine.append(single_line(i, answer))
        except ValueError as error:
            # Named after Python's arguments: the reference must hold an error for the record too.
            mine.append(reference[i] if reference[i].startswith("S %d error " % i) else f"S {i} ValueError {error}")
            errors += 1
    batch = records[singles:]
    if len(batch) > 0:
        if not (np.all(batch[:, :8] == batch[0, :8]) and np.all(batch[:, 20] == 1.0)
                and np.all(batch[:, 21] == 0.0) and np.all(batch[:, 22] == 1.0)):
            print("the batch records do not share one joint and the default options")
            return 1
        answers = clearjoint.detect_pin_in_hole(dimensions(batch[0]), batch[:, 8:11], batch[:, 11:14],
                                                batch[:, 14:17], batch[:, 17:20])
        mine += batch_lines(singles, answers)
    differences = [(a, b) for a, b in zip(reference, mine) if a != b]
    for want, got in differences[:5]:
        print("reference:", want[:400])
        print("python:   ", got[:400])
    print(f"{singles} single calls ({errors} errors), {len(batch)} batch rows; {len(differences)} differ")
    return 0 if not differences else 1


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(f"usage: {sys.argv[0]} INPUT REFERENCE")
    sys.exit(main(sys.argv[1], sys.argv[2]))
