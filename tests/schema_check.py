#!/usr/bin/env python3
"""The JSON Schemas (schemas/) against the loaders, with the standard validator.

schema_check.py AFFORD SOURCE_DIR WORK_DIR

1. `afford schema --all` writes exactly the files committed in schemas/.
2. Every shipped YAML file validates against its kind's schema.
3. Schema and loader agree on the keys: in every mapping of every shipped
   file, an extra unknown key and each required key left out are rejected
   by both the schema and the loader (`afford check`, file:line:col), and an
   optional key left out is not reported missing by the loader. The
   mutations come from the schemas, which come from the loaders' tables, so
   a key added to one side only fails here.
4. The broken files under tests/ that the loader rejects for an unknown or a
   missing key are rejected by the schema too.
Exit status 0 when all hold, 1 otherwise.
"""
import copy
import glob
import json
import os
import re
import shutil
import subprocess
import sys

import jsonschema
import yaml  # its C reader and writer (libyaml): the pure-Python writer took most of the run

SHIPPED = ["objects/*.yaml", "actees/*.yaml", "agents/*.yaml", "rules/*.yaml", "sessions/*.yaml",
           "devices/*.yaml", "tests/rules/*.yaml", "measurements/*.yaml"]
BROKEN = ["tests/data/**/*.yaml"]
UNKNOWN_KEY = "not_a_key_of_this_mapping"
# A file's kind is its first key; the schema of a rule test is rule_test.
SCHEMA_OF_KIND = {"test": "rule_test"}
# The loader's errors about keys (engine/base/yaml_reader.cpp, MapReader).
KEY_ERROR = re.compile(r"expected one of the keys of|found no such key")

failures = []


def fail(message):
    failures.append(message)
    print("FAIL " + message)


def load_schemas(folder):
    schemas = {}
    for path in sorted(glob.glob(os.path.join(folder, "*.schema.json"))):
        kind = os.path.basename(path)[: -len(".schema.json")]
        with open(path, encoding="utf-8") as f:
            schemas[kind] = json.load(f)
    return schemas


def schema_for(schemas, document):
    if not isinstance(document, dict) or not document:
        return None
    first = next(iter(document))
    return schemas.get(SCHEMA_OF_KIND.get(first, first))


def is_valid(schema, instance):
    return jsonschema.Draft7Validator(schema).is_valid(instance)


def mappings(instance, schema, path=()):
    """Every mapping in `instance` with the schema of its keys, by path."""
    if "anyOf" in schema:
        for alternative in schema["anyOf"]:
            if is_valid(alternative, instance):
                yield from mappings(instance, alternative, path)
                return
        return
    if "properties" in schema and isinstance(instance, dict):
        properties, required = effective(schema, instance)
        yield path, required
        for key, value in instance.items():
            if key in properties:
                yield from mappings(value, properties[key], path + (key,))
    elif "items" in schema and isinstance(instance, list):
        for i, item in enumerate(instance):
            # [first] with additionalItems: the first element's own schema.
            items = schema["items"]
            if isinstance(items, list):
                items = items[i] if i < len(items) else schema["additionalItems"]
            yield from mappings(item, items, path + (i,))


def effective(schema, instance):
    """The properties and required keys of a mapping's schema for this
    instance: with the if/then/else of its allOf applied."""
    properties = dict(schema["properties"])
    required = list(schema.get("required", []))
    for condition in schema.get("allOf", []):
        if "if" not in condition:
            continue
        branch = condition["then"] if is_valid(condition["if"], instance) else condition.get("else", {})
        properties.update(branch.get("properties", {}))
        required += branch.get("required", [])
    return properties, required


def at(document, path):
    for step in path:
        document = document[step]
    return document


def mutations(document, schema):
    """(name, mutated document, required, what the loader's error must
    mention): required tells whether the mutation leaves out a required key
    or adds one (both to be rejected) or leaves out an optional one, which
    the loader must not report as a missing key."""
    for path, required in mappings(document, schema):
        # A rule test with `error:` loads its session's files only when it
        # runs (afford check reads the case and the session's own keys), so
        # what lies deeper is checked through the session files instead.
        if "test" in document and "error" in document and len(path) > 1 and path[0] == "session":
            continue
        where = "/".join(str(p) for p in path) or "the top"
        added = copy.deepcopy(document)
        at(added, path)[UNKNOWN_KEY] = "1"
        yield "unknown key at " + where, added, True, "'" + UNKNOWN_KEY + "'"
        for key in list(at(document, path)):
            removed = copy.deepcopy(document)
            del at(removed, path)[key]
            # Without its first key a file is of no kind: the error names
            # the kinds instead of the key.
            mention = key if not path and key == next(iter(document)) else "'" + key + "'"
            yield "no " + key + " at " + where, removed, key in required, mention


def mirror(source, work, relative_dir):
    """A tree under work/tree/main in which relative_dir is a real, writable
    folder and everything else links to the source, so that the relative
    paths a mutated file names resolve as they do for the original."""
    root = os.path.join(work, "tree", "main")
    shared = os.path.join(work, "tree", "shared")
    if not os.path.lexists(shared):
        os.makedirs(os.path.dirname(shared), exist_ok=True)
        os.symlink(os.path.join(os.path.dirname(os.path.abspath(source)), "shared"), shared)
    here, there = root, os.path.abspath(source)
    for part in [""] + relative_dir.split(os.sep):
        here, there = os.path.join(here, part), os.path.join(there, part)
        if os.path.islink(here):
            os.unlink(here)
        os.makedirs(here, exist_ok=True)
        for entry in os.listdir(there):
            if not os.path.lexists(os.path.join(here, entry)):
                os.symlink(os.path.join(there, entry), os.path.join(here, entry))
    return os.path.join(root, relative_dir)


def check_files(afford, paths):
    """afford check on each path: {path: its error line, or None if ok}."""
    result = {}
    for start in range(0, len(paths), 200):
        batch = paths[start:start + 200]
        run = subprocess.run([afford, "check"] + batch, capture_output=True, text=True)
        for path in batch:
            result[path] = None
        for line in run.stderr.splitlines():
            for path in batch:
                if line.startswith(path + ":"):
                    result[path] = line
    return result


def main():
    afford, source, work = sys.argv[1], sys.argv[2], sys.argv[3]
    shutil.rmtree(work, ignore_errors=True)  # no file of an earlier run is checked
    generated = os.path.join(work, "generated")
    os.makedirs(generated, exist_ok=True)
    subprocess.run([afford, "schema", "--all", "--out", generated], check=True)

    # 1. The committed copies are what the program writes.
    committed_dir = os.path.join(source, "schemas")
    committed = sorted(os.path.basename(p) for p in glob.glob(os.path.join(committed_dir, "*.schema.json")))
    written = sorted(os.path.basename(p) for p in glob.glob(os.path.join(generated, "*.schema.json")))
    if committed != written:
        fail("schemas/ holds %s, afford schema --all writes %s" % (committed, written))
    for name in written:
        with open(os.path.join(generated, name), encoding="utf-8") as a:
            fresh = a.read()
        old_path = os.path.join(committed_dir, name)
        old = open(old_path, encoding="utf-8").read() if os.path.exists(old_path) else None
        if fresh != old:
            fail("schemas/%s differs from what afford writes: run afford schema --all --out schemas" % name)
    schemas = load_schemas(generated)
    for schema in schemas.values():
        jsonschema.Draft7Validator.check_schema(schema)

    # 2. Every shipped file validates.
    shipped = sorted(p for pattern in SHIPPED for p in glob.glob(os.path.join(source, pattern)))
    documents = {}
    for path in shipped:
        with open(path, encoding="utf-8") as f:
            document = yaml.load(f, Loader=yaml.CSafeLoader)
        schema = schema_for(schemas, document)
        if schema is None:
            fail("%s: no schema for its first key" % path)
            continue
        errors = list(jsonschema.Draft7Validator(schema).iter_errors(document))
        for e in errors:
            fail("%s: %s: %s" % (path, "/".join(str(p) for p in e.absolute_path), e.message))
        if not errors:
            documents[path] = (document, schema)
    print("%d shipped files validate" % len(documents))

    # 3. Mutations: rejected by the schema and by the loader.
    has_shared = os.path.isdir(os.path.join(os.path.dirname(os.path.abspath(source)), "shared", "data"))
    expected = {}  # mutated file -> (what, mention)
    originals = []
    count = 0
    for path, (document, schema) in documents.items():
        relative = os.path.relpath(path, source)
        if relative.startswith("measurements") and not has_shared:
            continue  # its traces are in ../shared (tests/CMakeLists.txt)
        folder = mirror(source, work, os.path.dirname(relative))
        stem = os.path.splitext(os.path.basename(path))[0]
        original = os.path.join(folder, "%s.original.yaml" % stem)
        with open(original, "w", encoding="utf-8") as f:
            yaml.dump(document, f, Dumper=yaml.CSafeDumper, sort_keys=False, allow_unicode=True)
        originals.append(original)
        for i, (what, mutated, rejected, mention) in enumerate(mutations(document, schema)):
            count += 1
            if rejected and is_valid(schema, mutated):
                fail("%s, %s: the schema accepts it" % (relative, what))
            target = os.path.join(folder, "%s.mutation-%03d.yaml" % (stem, i))
            with open(target, "w", encoding="utf-8") as f:
                yaml.dump(mutated, f, Dumper=yaml.CSafeDumper, sort_keys=False, allow_unicode=True)
            expected[target] = (relative + ", " + what, rejected, mention)
    # The copies load unchanged, so that a mutation's error is the mutation's.
    for path, error in check_files(afford, originals).items():
        if error is not None:
            fail("the unmutated copy does not load: " + error)
    location = re.compile(r"^[^:]+:[0-9]+:[0-9]+: expected ")
    for path, error in check_files(afford, sorted(expected)).items():
        what, rejected, mention = expected[path]
        if not rejected:
            # An optional key left out: the file may fail for other reasons
            # (a default that does not fit), but not for that key missing.
            if error is not None and "key " + mention in error and "found no such key" in error:
                fail("%s: the loader requires the key, the schema does not: %s" % (what, error))
            continue
        if error is None:
            fail("%s: the loader accepts it" % what)
        elif not location.match(error) or mention not in error:
            fail("%s: the loader's error is not about %s at file:line:col: %s" % (what, mention, error))
    print("%d mutations checked against the schemas and the loader" % count)

    # 4. Broken files the loader rejects for a key: the schema rejects them.
    broken = sorted(p for pattern in BROKEN for p in glob.glob(os.path.join(source, pattern), recursive=True))
    key_errors = 0
    for path, error in check_files(afford, broken).items():
        if error is None or not KEY_ERROR.search(error):
            continue
        key_errors += 1
        with open(path, encoding="utf-8") as f:
            document = yaml.load(f, Loader=yaml.CSafeLoader)
        schema = schema_for(schemas, document)
        if schema is None or is_valid(schema, document):
            fail("%s: the loader rejects it (%s) but the schema accepts it" % (path, error))
    if key_errors == 0:
        fail("no broken file under tests/ with a key error: the check of step 4 checked nothing")
    print("%d broken files with a key error are rejected by the schema too" % key_errors)

    print("%d failures" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
