#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Scores `clearjoint detect` answers (or any code's answers in that format) against the reference
answers of the detection suite's robustness export.

    python3 bench/detection/score_detect_answers.py REFERENCE.jsonl ANSWERS.jsonl [--list N]

REFERENCE.jsonl: `<family>.reference.jsonl` from `detection_suite export`. ANSWERS.jsonl: one answer
line per input line of `<family>.jsonl`, matched by "id". Scores with the definitions of
docs/reports/benchmarks.md: wrong scenario, missed and spurious contacts (keyed by type and base,
two arcs of one rim matched by nearest journal point), the largest contact-point and crossing
errors, and the depth relative errors. Contact points of a rim beyond a base all round
(ill-conditioned when the rim is nearly parallel to the base) are tallied apart. Answers with
"error" count as errors. Standard library only.
Exit status: 0 when every answer has the reference scenario and contacts, 1 otherwise, 2 on bad
files.
"""

import argparse
import json
import math
import sys


def read_lines(path):
    lines = {}
    order = []
    with open(path) as f:
        for number, text in enumerate(f, 1):
            if not text.strip():
                continue
            try:
                line = json.loads(text)
            except json.JSONDecodeError as error:
                raise ValueError(f"{path}:{number}: not JSON: {error}") from None
            if not isinstance(line, dict):
                raise ValueError(f"{path}:{number}: expected a JSON object, got {text.strip()[:60]}")
            key = json.dumps(line.get("id"))
            lines[key] = line
            order.append(key)
    return lines, order


def distance(p, q):
    return math.dist(p, q)


def percentile(values, fraction):
    if not values:
        return float("nan")
    values = sorted(values)
    rank = max(1, math.ceil(fraction * len(values)))
    return values[min(len(values), rank) - 1]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("reference")
    parser.add_argument("answers")
    parser.add_argument("--list", type=int, default=10, help="failures to print (default 10)")
    args = parser.parse_args()
    try:
        reference, order = read_lines(args.reference)
        answers, _ = read_lines(args.answers)
    except (OSError, ValueError) as error:
        print(f"score_detect_answers: {error}", file=sys.stderr)
        return 2

    counts = dict(inputs=0, undecided=0, no_answer=0, errors=0, wrong_scenario=0, missed=0, spurious=0)
    point_errors, crossing_errors, depth_errors, all_round_errors = [], [], [], []
    failures = []
    for key in order:
        ref = reference[key]
        for field in ("scenario", "contacts"):
            if field not in ref:
                print(f"score_detect_answers: {args.reference}: line with id {key}: missing \"{field}\"",
                      file=sys.stderr)
                return 2
        counts["inputs"] += 1
        if not ref.get("reference", {}).get("decided", True):
            counts["undecided"] += 1
            continue
        answer = answers.get(key)
        problems = []
        if answer is None:
            counts["no_answer"] += 1
            problems.append("no answer line")
        elif "error" in answer:
            counts["errors"] += 1
            problems.append(f"error: {answer['error']}")
        else:
            if answer.get("scenario") != ref["scenario"]:
                counts["wrong_scenario"] += 1
                problems.append(f"scenario {answer.get('scenario')}, reference {ref['scenario']}")
            unused = list(ref["contacts"])
            for contact in answer.get("contacts", []):
                same = [r for r in unused if r["type"] == contact["type"] and r["base"] == contact["base"]]
                if not same:
                    counts["spurious"] += 1
                    problems.append(f"spurious {contact['type']} contact at {contact['base']}")
                    continue
                match = min(same, key=lambda r: distance(r["point_journal"], contact["point_journal"]))
                unused.remove(match)
                if not match.get("points_defined", True):
                    continue
                error = max(distance(match["point_journal"], contact["point_journal"]),
                            distance(match["point_bearing"], contact["point_bearing"]))
                (all_round_errors if match.get("rim_beyond_base_all_round") else point_errors).append(error)
                if match["depth"] > 0:
                    depth_errors.append(abs(contact["depth"] - match["depth"]) / match["depth"])
                for crossing in contact.get("crossings", []):
                    if match["crossings"]:
                        crossing_errors.append(min(distance(crossing, r) for r in match["crossings"]))
            for missed in unused:
                counts["missed"] += 1
                problems.append(f"missed {missed['type']} contact at {missed['base']}")
        if problems:
            failures.append((ref["id"], problems))

    print(f"inputs {counts['inputs']} (reference undecided {counts['undecided']}), answers missing "
          f"{counts['no_answer']}, error lines {counts['errors']}")
    print(f"wrong scenarios {counts['wrong_scenario']}, missed contacts {counts['missed']}, "
          f"spurious contacts {counts['spurious']}")
    for name, values in (("contact-point error (input units)", point_errors),
                         ("crossing error (input units)", crossing_errors),
                         ("depth relative error", depth_errors),
                         ("contact-point error, rims beyond a base all round", all_round_errors)):
        print(f"{name}: median {percentile(values, 0.5):.3g}, p99 {percentile(values, 0.99):.3g}, "
              f"max {max(values) if values else float('nan'):.3g} over {len(values)}")
    for identifier, problems in failures[:args.list]:
        print(f"  {identifier}: {'; '.join(problems)}")
    return 0 if not failures else 1


if __name__ == "__main__":
    sys.exit(main())
