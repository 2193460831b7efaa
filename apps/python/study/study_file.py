# SPDX-License-Identifier: BSD-3-Clause
"""Reading a study file: JSON Schema validation (docs/schema/study-v1.schema.json), then the
checks a schema cannot express (names that must refer to each other). Every error names the file,
the field and the value."""
import copy
import json
import math
import os
from dataclasses import dataclass, field

import jsonschema

from .._bounded_files import MAX_DESCRIPTION_BYTES, read_text_bounded

SCHEMA_FILE = "study-v1.schema.json"
# The most runs a study may expand to, counted before expanding (points x members per design):
# each run is a file in one folder and a task on the scheduler, and a typo such as members = 1e9
# should be an error, not the client running out of memory. Section 6's largest study has 153.
MAX_RUNS = 100_000
# The engine a run is integrated in when neither the study nor its design names one: that of
# clearjoint.simulate and `clearjoint simulate`.
DEFAULT_ENGINE = "clearjoint"


class StudyError(ValueError):
    """A study file, a model or a store that cannot be used as given; the message names the field."""


def _schema_path():
    """The schema ships inside the package (copied there by the build); in a source checkout it
    is read from docs/schema/ directly."""
    here = os.path.dirname(os.path.abspath(__file__))
    candidates = [os.path.join(here, SCHEMA_FILE),
                  os.path.join(here, "..", "..", "..", "..", "docs", "schema", SCHEMA_FILE)]
    for path in candidates:
        if os.path.exists(path):
            return path
    raise StudyError("the study schema %s is missing from %s (a broken install)" % (SCHEMA_FILE, here))


def schema():
    with open(_schema_path()) as f:
        return json.load(f)


class _NonFinite:
    """NaN, Infinity or -Infinity as read (Python's json module accepts them; JSON has no such
    numbers), kept as a marker so that the error can name the field."""

    def __init__(self, text):
        self.text = text


def _read_json(path, what):
    """The text of a study or model file of at most MAX_DESCRIPTION_BYTES (the limit of model
    files) and its JSON value, read with _bounded_files: a FIFO, a device such as /dev/zero, a
    symbolic link or a larger file is refused (ValueError naming `what`, the path and the limit)
    before it is read."""
    text = read_text_bounded(path, what, MAX_DESCRIPTION_BYTES)
    return text, json.loads(text, parse_constant=_NonFinite)


def _non_finite_field(value, where=()):
    """The path of the first NaN or Infinity in value, or None."""
    if isinstance(value, _NonFinite):
        return where, value.text
    children = value.items() if isinstance(value, dict) else enumerate(value) if isinstance(value, list) else ()
    for key, child in children:
        found = _non_finite_field(child, where + (key,))
        if found:
            return found
    return None


def _reject_non_finite(path, what, value):
    found = _non_finite_field(value)
    if found:
        where, text = found
        raise StudyError("%s: %s%s: %s is not a JSON number (JSON has no NaN or Infinity; give a finite "
                         "number)" % (path, what, _field_name(where), text))


def _field_name(path):
    """jsonschema's error path as designs[2].grid.radial."""
    text = ""
    for part in path:
        text += "[%d]" % part if isinstance(part, int) else ("." if text else "") + str(part)
    return text or "(top level)"


@dataclass
class Study:
    """A validated study file: its fields as read, the directory relative paths start from, and
    the base models loaded (key "" is the study's model, others are design names)."""
    path: str
    spec: dict
    base_models: dict = field(default_factory=dict)
    text: str = ""  # the study file as read (its hash goes into the store's study.json)

    @property
    def name(self):
        return self.spec["name"]

    @property
    def directory(self):
        return os.path.dirname(os.path.abspath(self.path))

    def resolve(self, relative):
        return os.path.normpath(os.path.join(self.directory, relative))

    @property
    def store_path(self):
        return self.resolve(self.spec["store"])

    @property
    def parameters(self):
        return self.spec.get("parameters", {})

    @property
    def reductions(self):
        return self.spec["outputs"].get("reductions", [])

    def engine_of(self, design):
        """The engine a design's runs are integrated in: the design's, else the study's, else
        DEFAULT_ENGINE."""
        return design.get("engine", self.spec.get("engine", DEFAULT_ENGINE))

    def design(self, name):
        for d in self.spec["designs"]:
            if d["name"] == name:
                return d
        raise StudyError("%s: no design called %r (designs: %s)" % (
            self.path, name, ", ".join(d["name"] for d in self.spec["designs"])))


def _load_model(study_path, where, model):
    """A model given inline or as a path relative to the study file."""
    if isinstance(model, dict):
        return copy.deepcopy(model)
    path = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(study_path)), model))
    try:
        _, loaded = _read_json(path, "the model file")
    except json.JSONDecodeError as error:
        raise StudyError("%s: %s = %r: %s is not JSON (%s)" % (study_path, where, model, path, error))
    except FileNotFoundError:
        raise StudyError("%s: %s = %r: cannot read %s (no such file)" % (study_path, where, model, path))
    except ValueError as error:  # _bounded_files' refusal: it names the file and the limit
        raise StudyError("%s: %s = %r: %s" % (study_path, where, model, error))
    _reject_non_finite(study_path, "%s = %r: %s: " % (where, model, path), loaded)
    return loaded


REDUCTION_NEEDS = {  # quantity -> fields it needs
    "peak_abs": ("table", "column"),
    "percentile_abs": ("table", "column", "percentile"),
    "rms": ("table", "column"),
    "energy_loss": (),
    "impacts": ("table",),
    "max_depth": ("table",),
}


def _choices(parameter):
    """The choices of a parameter whose set entries pick from lists (study-v1 schema: choices),
    the shortest list's length bounding its values; None for a numeric parameter."""
    lists = [target["choices"] for target in parameter["set"] if "choices" in target]
    return min(lists, key=len) if lists else None


def _check_choices(path, parameters):
    for name, parameter in parameters.items():
        for k, target in enumerate(parameter["set"]):
            if "choices" in target and ("scale" in target or "offset" in target):
                raise StudyError("%s: parameters.%s.set[%d]: choices cannot be combined with scale or offset "
                                 "(the value is the choice's index)" % (path, name, k))


def _check_choice_values(where, design, parameters):
    """A parameter with choices takes whole numbers that index every list of choices."""
    for kind in ("grid", "zip", "fixed", "random"):
        block = design.get(kind, {})
        if kind == "random":
            block = block.get("distributions", {}) if block else {}
        for name, values in block.items():
            choices = _choices(parameters[name]) if name in parameters else None
            if choices is None:
                continue
            if kind == "random":
                raise StudyError("%s: random.%s: a parameter with choices takes listed values (grid, zip or "
                                 "fixed), not draws" % (where, name))
            for value in values if isinstance(values, list) else [values]:
                if not (value == int(value) and 0 <= value < len(choices)):
                    raise StudyError("%s: %s.%s = %r: must be a whole number from 0 to %d, the index of one of "
                                     "its choices (%s)" % (where, kind, name, value, len(choices) - 1,
                                                           ", ".join(json.dumps(c) for c in choices)))


def _check_references(path, spec):
    """What the schema cannot say: designs name declared parameters, names are unique, members
    above 1 have an ensemble to draw them from, plots name designs and reductions that exist."""
    parameters = spec.get("parameters", {})
    _check_choices(path, parameters)
    names = [d["name"] for d in spec["designs"]]
    duplicates = sorted({n for n in names if names.count(n) > 1})
    if duplicates:
        raise StudyError("%s: designs: the name %r is used twice" % (path, duplicates[0]))
    for i, design in enumerate(spec["designs"]):
        where = "%s: designs[%d] (%r)" % (path, i, design["name"])
        kinds = [k for k in ("grid", "zip", "random") if k in design]
        if len(kinds) > 1:
            raise StudyError("%s: give one of grid, zip, random, not %s" % (where, " and ".join(kinds)))
        used = []
        for kind in kinds:
            block = design[kind]["distributions"] if kind == "random" else design[kind]
            used += [(kind, name) for name in block]
        used += [("fixed", name) for name in design.get("fixed", {})]
        for kind, name in used:
            if name not in parameters:
                raise StudyError("%s: %s.%s: no such parameter (parameters: %s)" % (
                    where, kind, name, ", ".join(parameters) or "none"))
        seen = [name for _, name in used]
        twice = sorted({n for n in seen if seen.count(n) > 1})
        if twice:
            raise StudyError("%s: parameter %r is given twice" % (where, twice[0]))
        if "zip" in design:
            lengths = {name: len(values) for name, values in design["zip"].items()}
            if len(set(lengths.values())) > 1:
                raise StudyError("%s: zip: the lists differ in length (%s)" % (
                    where, ", ".join("%s: %d" % item for item in lengths.items())))
        _check_choice_values(where, design, parameters)
        if design.get("members", 1) > 1 and "ensemble" not in spec:
            raise StudyError("%s: members = %d needs the study's ensemble (how members differ)" % (
                where, design["members"]))
        if "x" in design and design["x"] not in seen:
            raise StudyError("%s: x = %r is not a parameter the design varies or fixes" % (where, design["x"]))
    reductions = spec["outputs"].get("reductions", [])
    rnames = [r["name"] for r in reductions]
    for i, r in enumerate(reductions):
        if rnames.count(r["name"]) > 1:
            raise StudyError("%s: outputs.reductions[%d]: the name %r is used twice" % (path, i, r["name"]))
        if isinstance(r.get("after"), str) and not float(r["after"][:-1]) < 100:
            raise StudyError("%s: outputs.reductions[%d] (%r): after = %r: a share of the run must be below 100%% "
                             "(no sample would be left)" % (path, i, r["name"], r["after"]))
        for needed in REDUCTION_NEEDS[r["quantity"]]:
            if needed not in r:
                raise StudyError("%s: outputs.reductions[%d] (%r): quantity %r needs %r" % (
                    path, i, r["name"], r["quantity"], needed))
    for i, plot in enumerate(spec.get("plots", [])):
        for name in plot["designs"]:
            if name not in names:
                raise StudyError("%s: plots[%d].designs: no design called %r" % (path, i, name))
            if "x" not in next(d for d in spec["designs"] if d["name"] == name):
                raise StudyError("%s: plots[%d].designs: design %r has no x (the parameter to plot against)" % (
                    path, i, name))
        for name in plot["statistics"]:
            if name not in rnames:
                raise StudyError("%s: plots[%d].statistics: no reduction called %r (reductions: %s)" % (
                    path, i, name, ", ".join(rnames) or "none"))


def _design_points(design):
    """How many points a design has, before expanding it."""
    if "grid" in design:
        return math.prod(len(values) for values in design["grid"].values())
    if "zip" in design:
        return max((len(values) for values in design["zip"].values()), default=1)
    if "random" in design:
        return design["random"]["draws"]
    return 1


def _check_size(path, spec):
    """At most MAX_RUNS runs, counted per design as points x members (points that designs share
    are counted once per design: an upper bound)."""
    total = 0
    for i, design in enumerate(spec["designs"]):
        points, members = _design_points(design), design.get("members", 1)
        runs = points * members
        if runs > MAX_RUNS:
            raise StudyError("%s: designs[%d] (%r): %d points x %d members = %d runs, more than the %d a study "
                             "may hold" % (path, i, design["name"], points, members, runs, MAX_RUNS))
        total += runs
    if total > MAX_RUNS:
        raise StudyError("%s: designs: %d runs in all, more than the %d a study may hold" % (path, total, MAX_RUNS))


def _integers(spec):
    """JSON Schema counts 3.0 as an integer; the expansion needs Python ints."""
    for design in spec["designs"]:
        if "members" in design:
            design["members"] = int(design["members"])
        if "random" in design:
            for key in ("draws", "seed"):
                design["random"][key] = int(design["random"][key])


def load_study(path):
    """Reads and checks a study file; raises StudyError naming the field and value at fault."""
    try:
        text, spec = _read_json(path, "the study file")
    except json.JSONDecodeError as error:
        raise StudyError("%s: not JSON (%s)" % (path, error))
    except FileNotFoundError:
        raise StudyError("%s: cannot read the study file (no such file)" % path)
    except ValueError as error:  # _bounded_files' refusal: it names the file and the limit
        raise StudyError(str(error))
    _reject_non_finite(path, "", spec)
    validator = jsonschema.Draft202012Validator(schema())
    errors = sorted(validator.iter_errors(spec), key=lambda e: list(e.absolute_path))
    if errors:
        e = jsonschema.exceptions.best_match(errors)
        message = e.message
        if e.validator == "pattern" and list(e.absolute_path)[-1:] == ["after"]:
            message = "%r is neither a time in seconds nor a share of the run such as \"50%%\"" % e.instance
        raise StudyError("%s: %s: %s" % (path, _field_name(e.absolute_path), message))
    _integers(spec)
    _check_references(path, spec)
    _check_size(path, spec)
    study = Study(path=path, spec=spec, text=text)
    study.base_models[""] = _load_model(path, "model", spec["model"])
    for design in spec["designs"]:
        if "model" in design:
            study.base_models[design["name"]] = _load_model(path, "designs.%s.model" % design["name"],
                                                            design["model"])
    return study
