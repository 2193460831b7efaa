#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes the fuzz targets' seed corpora (fuzz/corpus/<target>/) from the repository's own
inputs: every line of examples/*.jsonl and tests/apps/*.jsonl (intersect and detect lines), the
model files of models/ (model reader), and the joints of examples/joints.jsonl as raw doubles
(detection on raw doubles, in fuzz_detect_raw's input layout). Run from anywhere; rewrites the
corpora in place, so that they follow the examples when those change.

    /usr/bin/python3 fuzz/make_seed_corpus.py
"""
import hashlib
import json
import pathlib
import struct

ROOT = pathlib.Path(__file__).resolve().parent.parent
CORPUS = ROOT / "fuzz" / "corpus"


def write(target: str, data: bytes) -> None:
    folder = CORPUS / target
    folder.mkdir(parents=True, exist_ok=True)
    # Named by content, as libFuzzer names the inputs it adds.
    (folder / hashlib.sha1(data).hexdigest()).write_bytes(data)


def jsonl_lines(*patterns: str):
    for pattern in patterns:
        for path in sorted(ROOT.glob(pattern)):
            for line in path.read_text().splitlines():
                if line.strip():
                    yield line


def raw_joint(query: dict) -> bytes:
    """fuzz_detect_raw's raw mode: a joint's 16 doubles (bearing radius, length, journal radius,
    length, bearing centre and axis, journal centre and axis), little-endian, then the two bytes
    FuzzedDataProvider takes from the end (the unit exponent byte, 0x3c: no change of units,
    and the mode byte, 1: raw)."""
    b, j = query["bearing"], query["journal"]
    values = [b["radius"], b["length"], j["radius"], j["length"],
              *b["center"], *b["axis"], *j["center"], *j["axis"]]
    return struct.pack("<16d", *values) + bytes([0x3C, 1])


def main() -> None:
    for line in jsonl_lines("examples/rims.jsonl", "tests/apps/bad_lines.jsonl",
                            "tests/apps/number_ids.jsonl"):
        write("fuzz_intersect_lines", line.encode())
    detect_lines = list(jsonl_lines("examples/joints.jsonl", "tests/apps/detect_*.jsonl"))
    for line in detect_lines:
        write("fuzz_detect_lines", line.encode())
    for path in sorted(ROOT.glob("models/**/*.json")):
        write("fuzz_model_file", path.read_bytes())
    for line in detect_lines:
        try:
            query = json.loads(line)
            write("fuzz_detect_raw", raw_joint(query))
        except (ValueError, KeyError, TypeError, struct.error):
            continue  # the bad lines of the detect tests have no joint to take


if __name__ == "__main__":
    main()
