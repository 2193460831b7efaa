# SPDX-License-Identifier: BSD-3-Clause
"""A study's points and runs: the union of its designs (grids, element-wise lists, seeded random
draws), each point with its ensemble members, each member a complete model.

A point is a set of parameter values on a base model; its id spells them out
("axial_clearance_mm=0.1,radial_clearance_mm=0.05"), so that the same point named by two designs is
one point. Member k (k = -(n-1)/2 .. n/2, rounded down; k = 0 for a single member) scales the
ensemble's values by 1 + k relative_step. A run is identified by the SHA-256 of the model it runs,
of the outputs kept and of the engine when it is not the default: two (point, member) pairs with
the same model in the same engine are one run.

The engine (the study's or a design's `engine`, "clearjoint" by default) is part of the point:
a point run in Simbody has "engine=simbody" in its id, so two designs that differ only in their
engine are two sets of points, drawn as two lines. The default engine adds nothing to the ids,
so that stores made before studies named engines keep their runs.
"""
import copy
import hashlib
import itertools
import json
from dataclasses import dataclass

import numpy as np

from . import json_pointer
from .preflight import check_runs
from .study_file import DEFAULT_ENGINE, StudyError


@dataclass(frozen=True)
class Point:
    point_id: str
    base: str          # "" for the study's model, else the design whose model it uses
    values: tuple      # ((parameter, value), ...) in the study's parameter order
    designs: tuple     # the designs that contain it, in file order
    members: int
    engine: str = DEFAULT_ENGINE  # the engine that integrates it (clearjoint.simulate's engine)

    def value(self, name):
        return dict(self.values)[name]


@dataclass(frozen=True)
class Run:
    run_id: str
    point_id: str
    member: int
    model: dict
    model_sha256: str
    engine: str = DEFAULT_ENGINE


def canonical_json(value):
    """Deterministic JSON text: sorted keys, shortest round-trip floats."""
    return json.dumps(value, sort_keys=True, separators=(",", ":"), allow_nan=False)


def sha256_text(text):
    return hashlib.sha256(text.encode()).hexdigest()


def member_offsets(members):
    """-4..4 for 9 members, 0 for one: k = 0 is always the point's model unchanged."""
    first = -((members - 1) // 2)
    return list(range(first, first + members))


def _format_value(value):
    return repr(float(value))


def point_id(base, values, engine=DEFAULT_ENGINE):
    parts = ["%s=%s" % (name, _format_value(v)) for name, v in sorted(values)]
    if engine != DEFAULT_ENGINE:
        parts.insert(0, "engine=%s" % engine)
    if base:
        parts.insert(0, "model=%s" % base)
    return ",".join(parts) or "base"


def run_key(model_hash, outputs_hash, engine=DEFAULT_ENGINE):
    """A run's id: the first 20 hex digits of the SHA-256 of its model's hash, the outputs' hash
    and, for an engine other than the default, the engine's name."""
    text = model_hash + outputs_hash + ("" if engine == DEFAULT_ENGINE else "\nengine=%s" % engine)
    return sha256_text(text)[:20]


def _draw(rng, distribution, count):
    (kind, arguments), = distribution.items()
    a, b = arguments
    if kind == "uniform":
        return rng.uniform(a, b, count)
    if kind == "loguniform":
        return np.exp(rng.uniform(np.log(a), np.log(b), count))
    if kind == "normal":
        return rng.normal(a, b, count)
    return rng.lognormal(a, b, count)


def design_assignments(design):
    """The parameter values of each point of one design, in the design's order."""
    fixed = list(design.get("fixed", {}).items())
    if "grid" in design:
        names = list(design["grid"])
        rows = [list(zip(names, combination))
                for combination in itertools.product(*(design["grid"][n] for n in names))]
    elif "zip" in design:
        names = list(design["zip"])
        rows = [list(zip(names, combination)) for combination in zip(*(design["zip"][n] for n in names))]
    elif "random" in design:
        spec = design["random"]
        # One generator per design, parameters drawn in the file's order: the same file gives the
        # same points on every machine (NumPy's PCG64 stream is stable across platforms).
        rng = np.random.default_rng(spec["seed"])
        names = list(spec["distributions"])
        columns = [_draw(rng, spec["distributions"][n], spec["draws"]) for n in names]
        rows = [list(zip(names, (float(c[k]) for c in columns))) for k in range(spec["draws"])]
    else:
        rows = [[]]
    return [row + fixed for row in rows]


def expand_points(study):
    """The study's points, in the order the designs first name them."""
    order = list(study.parameters)
    points = {}
    for design in study.spec["designs"]:
        base = design["name"] if "model" in design else ""
        members = design.get("members", 1)
        engine = study.engine_of(design)
        for row in design_assignments(design):
            values = tuple(sorted(((n, float(v)) for n, v in row), key=lambda item: order.index(item[0])))
            pid = point_id(base, values, engine)
            if pid in points:
                old = points[pid]
                designs = old.designs + ((design["name"],) if design["name"] not in old.designs else ())
                points[pid] = Point(pid, base, values, designs, max(old.members, members), engine)
            else:
                points[pid] = Point(pid, base, values, (design["name"],), members, engine)
    return list(points.values())


def build_model(study, point, member):
    """The model of one member of one point: base model, the study's settings, the parameters,
    then the ensemble's scaling."""
    model = copy.deepcopy(study.base_models[point.base])
    try:
        for pointer, value in study.spec.get("set", {}).items():
            json_pointer.set_value(model, pointer, value, create=True)
        for name, value in point.values:
            for target in study.parameters[name]["set"]:
                if "choices" in target:  # an index, checked by study_file against every list
                    json_pointer.set_value(model, target["path"], copy.deepcopy(target["choices"][int(value)]))
                else:
                    json_pointer.set_value(model, target["path"],
                                           target.get("offset", 0.0) + target.get("scale", 1.0) * value)
        if member != 0:
            ensemble = study.spec["ensemble"]
            factor = 1.0 + member * ensemble["relative_step"]
            for pointer in ensemble["scale"]:
                json_pointer.scale_values(model, pointer, factor)
    except KeyError as error:
        raise StudyError("%s: point %s, member %d: %s" % (study.path, point.point_id, member, error.args[0]))
    return model


def outputs_sha256(study):
    return sha256_text(canonical_json(study.spec["outputs"]))


def expand_study(study):
    """(points, runs, membership): membership maps (point id, member) to a run id; runs are
    unique by run id, in the order first needed. Raises StudyError for what preflight.check_runs
    finds."""
    points = expand_points(study)
    outputs_hash = outputs_sha256(study)
    runs, membership = {}, {}
    for point in points:
        for member in member_offsets(point.members):
            model = build_model(study, point, member)
            model_hash = sha256_text(canonical_json(model))
            run_id = run_key(model_hash, outputs_hash, point.engine)
            membership[(point.point_id, member)] = run_id
            if run_id not in runs:
                runs[run_id] = Run(run_id, point.point_id, member, model, model_hash, point.engine)
    check_runs(study, runs.values())
    return points, list(runs.values()), membership
