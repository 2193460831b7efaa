#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Checks files and program output against the JSON Schemas of docs/schema/.

usage:
  validate_json.py SCHEMA_DIR check-schemas
  validate_json.py SCHEMA_DIR files SCHEMA FILE...          (.jsonl: every non-blank line; else the document)
  validate_json.py SCHEMA_DIR run SCHEMA PROGRAM COMMAND FILE...
        runs `PROGRAM COMMAND FILE` for each FILE and validates every output line
  validate_json.py SCHEMA_DIR reject SCHEMA JSON...          every JSON text must be rejected
  validate_json.py SCHEMA_DIR named SCHEMA FILE              FILE names every field of SCHEMA
  validate_json.py SCHEMA_DIR named-by-help SCHEMA PROGRAM COMMAND
        `PROGRAM COMMAND --help` names every field of SCHEMA

The last two keep the hand-written lists of an answer's fields (the reference page, a command's
help) in step with the schema, which the program's own output keeps in step with the library's
result field lists ("run"): a field the library adds fails "run" until the schema has it, then
these until the lists name it. A field is named in a Markdown file as `key` or `parent.key`, in
a help text as "key".

SCHEMA is a file name in SCHEMA_DIR without ".schema.json" (e.g. detect-answer). The schemas
refer to each other by $id (urn:clearjoint:schema:v1:...); all of SCHEMA_DIR is loaded so that
those references resolve. Uses Debian's python3-jsonschema (Draft 2020-12).
"""
import json
import pathlib
import re
import subprocess
import sys

import jsonschema


def load_schemas(schema_dir):
    return {path.name[: -len(".schema.json")]: json.loads(path.read_text())
            for path in sorted(pathlib.Path(schema_dir).glob("*.schema.json"))}


def validator(schemas, name):
    store = {schema["$id"]: schema for schema in schemas.values()}
    resolver = jsonschema.RefResolver.from_schema(schemas[name], store=store)
    return jsonschema.Draft202012Validator(schemas[name], resolver=resolver)


def documents(path):
    """(where, document) for each document of a file: one per non-blank line of a .jsonl."""
    text = pathlib.Path(path).read_text()
    if not str(path).endswith(".jsonl"):
        yield str(path), json.loads(text)
        return
    for number, line in enumerate(text.splitlines(), start=1):
        if line.strip():
            yield f"{path}:{number}", json.loads(line)


def check(check_with, items):
    """Validates (where, document) pairs; returns the number of documents, exits on the first error."""
    count = 0
    for where, document in items:
        errors = sorted(check_with.iter_errors(document), key=lambda e: list(e.absolute_path))
        if errors:
            best = jsonschema.exceptions.best_match(errors)
            field = "/".join(str(p) for p in best.absolute_path) or "(the document)"
            sys.exit(f"FAIL {where}: {field}: {best.message}\n  {json.dumps(document)[:400]}")
        count += 1
    return count


def answer_fields(schema):
    """The property names of every object the schema defines in $defs."""
    return sorted({key for definition in schema.get("$defs", {}).values() if isinstance(definition, dict)
                   for key in definition.get("properties", {})})


def require_named(name, fields, text, where, pattern):
    missing = [key for key in fields if not re.search(pattern(re.escape(key)), text)]
    if missing:
        sys.exit(f"FAIL {where} does not name the {name} field(s) {', '.join(missing)}")
    print(f"{where} names all {len(fields)} fields of {name}")


def main(argv):
    schema_dir, mode = argv[1], argv[2]
    schemas = load_schemas(schema_dir)
    if mode == "check-schemas":
        ids = set()
        for name, schema in schemas.items():
            jsonschema.Draft202012Validator.check_schema(schema)
            if schema.get("$schema") != "https://json-schema.org/draft/2020-12/schema":
                sys.exit(f"FAIL {name}: $schema is not draft 2020-12")
            # One id form for every schema, the format version part of it: urn:clearjoint:schema:v1:NAME.
            if not re.fullmatch(r"urn:clearjoint:schema:v[0-9]+:[a-z][a-z-]*", schema.get("$id", "")):
                sys.exit(f"FAIL {name}: $id {schema.get('$id')!r} is not urn:clearjoint:schema:vN:NAME")
            ids.add(schema["$id"])
        if len(ids) != len(schemas) or not schemas:
            sys.exit("FAIL: schema ids are not distinct, or there are no schemas")
        print(f"{len(schemas)} schemas are valid draft 2020-12 schemas with versioned ids")
        return
    name = argv[3]
    check_with = validator(schemas, name)
    if mode == "files":
        count = sum(check(check_with, documents(path)) for path in argv[4:])
        print(f"{count} documents of {len(argv) - 4} files match {name}")
    elif mode == "run":
        program, command, files = argv[4], argv[5], argv[6:]
        count = 0
        for path in files:
            # Exit status 1 (some lines were error lines) is expected for files of bad lines.
            run = subprocess.run([program, command, path], capture_output=True, text=True, check=False)
            if run.returncode not in (0, 1):
                sys.exit(f"FAIL: {program} {command} {path} exited with {run.returncode}: {run.stderr}")
            lines = [(f"output of {command} {path}, line {k}", json.loads(line))
                     for k, line in enumerate(run.stdout.splitlines(), start=1)]
            if not lines:
                sys.exit(f"FAIL: {program} {command} {path} wrote nothing")
            count += check(check_with, lines)
        print(f"{count} output lines of {command} on {len(files)} files match {name}")
    elif mode == "reject":
        for text in argv[4:]:
            if check_with.is_valid(json.loads(text)):
                sys.exit(f"FAIL: {name} accepts {text}")
        print(f"{name} rejects all {len(argv) - 4} documents")
    elif mode == "named":
        path = argv[4]
        require_named(name, answer_fields(schemas[name]), pathlib.Path(path).read_text(), path,
                      lambda key: rf"`([\w.\[\]]*\.)?{key}`")
    elif mode == "named-by-help":
        program, command = argv[4], argv[5]
        run = subprocess.run([program, command, "--help"], capture_output=True, text=True, check=False)
        require_named(name, answer_fields(schemas[name]), run.stdout + run.stderr,
                      f"{command} --help", lambda key: rf'"{key}"')
    else:
        sys.exit(f"unknown mode {mode}")


if __name__ == "__main__":
    main(sys.argv)
