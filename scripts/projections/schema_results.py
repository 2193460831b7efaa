# SPDX-License-Identifier: BSD-3-Clause
"""The "properties" and "required" lists of the JSON schemas' result objects, written from the
result field lists, as the command line writes the fields (apps/clearjoint/result_json.hpp).

Each object's properties are those of its result's fields, plus the keys the table below names as
the command's own (an answer's "v" and "id", a contact's velocities); any other property is a field
the list no longer has and is dropped. A property keeps its place in the object and its
"description"; a new field's property comes last. Every field's key is required.
"""

# The result objects of the schemas: file, the object's $defs name, result type, the keys that
# are not fields.
SCHEMA_RESULTS = [
    ("docs/schema/detect-answer.schema.json", "contact", "Contact", ["approach_velocity", "tangential_velocity"]),
    ("docs/schema/detect-answer.schema.json", "answer", "JointContacts", ["v", "id"]),
    ("docs/schema/detect-answer.schema.json", "pin_in_hole_answer", "PinInHoleContacts", ["v", "id", "joint"]),
]

# The $defs each schema's results refer to: the result type whose object it is.
OBJECT_OF = {"Contact": "contact"}

KEPT = ("description",)


def _properties(field, enums):
    """{key: schema} of one field as `detect` writes it."""
    key, kind, value = field["key"], field["kind"], field["value"]
    if kind == "bound":
        return {key: {"$ref": "#/$defs/error_bound"}}
    if kind == "list":
        if value == "RimCrossing":  # the points, and their error bounds under "crossing_errors"
            return {key: {"type": "array", "maxItems": field["capacity"], "items": {"$ref": "#/$defs/vector"}},
                    "crossing_errors": {"type": "array", "maxItems": field["capacity"],
                                        "items": {"$ref": "#/$defs/error_bound"}}}
        if value in OBJECT_OF:
            return {key: {"type": "array", "maxItems": field["capacity"],
                          "items": {"$ref": f"#/$defs/{OBJECT_OF[value]}"}}}
    elif kind == "plain":
        simple = {"float": {"type": "number"}, "int": {"type": "integer"}, "bool": {"type": "boolean"},
                  "vector3": {"$ref": "#/$defs/vector"}}
        if value in simple:
            return {key: dict(simple[value])}
        if value == "Certificate":  # flat: its level, and its reason's sentence
            return {key: {"$ref": "#/$defs/certainty"}, f"{key}_reason": {"type": "string"}}
        if value in enums:
            return {key: {"enum": [e["key"] for e in enums[value]["entries"]]}}
    raise SystemExit(f"schema_results.py: no JSON schema for the field {key} ({kind} {value})")


def apply(schema, path, results, enums):
    """Rewrites, in place, the result objects of the schema at `path`."""
    described = {result["type"]: result for result in results}
    for file, name, result_type, extras in SCHEMA_RESULTS:
        if file != path or result_type not in described:
            continue
        node = schema["$defs"][name]
        generated = {}
        for field in described[result_type]["fields"]:
            generated.update(_properties(field, enums))
        old = node.get("properties", {})
        properties = {}
        for key, value in old.items():
            if key in generated:
                properties[key] = {**generated[key], **{k: v for k, v in value.items() if k in KEPT}}
            elif key in extras:
                properties[key] = value
        for key, value in generated.items():
            properties.setdefault(key, value)
        node["properties"] = properties
        required = [key for key in node.get("required", []) if key in generated or key in extras]
        node["required"] = required + [key for key in generated if key not in required]


# How `detect --help` shows a key's value, where the key alone says too little.
HELP_VALUES = {"v": "1", "scenario": '"none"|"a".."l"|"beyond_model"'}


def detect_help_lines(schema):
    """The answer's keys as `detect --help` lists them (apps/clearjoint/detect_command.cpp): C++
    string literal lines, an answer object with its contacts' keys, in the schema's order."""
    objects = schema["$defs"]

    def keys(name, nested):
        items = []
        for key in objects[name]["properties"]:
            text = f'"{key}"'
            if key in HELP_VALUES:
                text += f": {HELP_VALUES[key]}"
            elif key in nested:
                text += ": [" + keys(nested[key], {}) + "]"
            items.append(text)
        return "{" + ", ".join(items) + "}"

    text = keys("answer", {"contacts": "contact"})
    import textwrap
    lines = textwrap.wrap(text, 76, initial_indent="  ", subsequent_indent="   ", break_on_hyphens=False)
    escaped = [line.replace("\\", "\\\\").replace('"', '\\"') for line in lines]
    return [f'    "{line}\\n"' for line in escaped]
