#!/usr/bin/python3
"""The scenario schema with an independent validator (Python jsonschema, Draft 7).

Checks that schemas/scenario.schema.json is a valid Draft 7 schema, that every property
has a description naming its unit and that every default satisfies its own schema, then
validates every scenarios/*.yaml of the repository and tests/scenario/good/*.yaml with it.
When the mrsim binary exists, the resolved scenario `mrsim check` prints for each
scenarios/*.yaml must validate too, and read the same with PyYAML's YAML 1.1 safe_load
(what users plot with) as with YAML 1.2 (numbers stay numbers, strings stay strings).

Run by ctest as: /usr/bin/python3 THIS --binary MRSIM --source REPO --shared SHARED
Exit 0: pass; 1: failure (the reasons are printed).
"""
import argparse
import json
import pathlib
import re
import subprocess
import sys

import jsonschema
import yaml

# Text that names a unit in a description: SI units used by mrsim, or an explicit
# "no unit" / "dimensionless" / "unit of ..." for quantities without one.
UNIT = re.compile(r"(\b(Pa|Pa\.s|m|mm|s|N|kg/m\^3|m/s\^2|m/s|rad/s|J|m\^3)\b|no unit|dimensionless"
                  r"|unit of|unit is)")


class Yaml12Loader(yaml.SafeLoader):
    """PyYAML reads YAML 1.1 (`1e5` is a string, `yes` a boolean); mrsim and editors read
    YAML 1.2 core. This loader resolves plain scalars the YAML 1.2 way."""


Yaml12Loader.yaml_implicit_resolvers = {
    key: [(tag, regexp) for tag, regexp in resolvers
          if tag not in ("tag:yaml.org,2002:bool", "tag:yaml.org,2002:float",
                         "tag:yaml.org,2002:int")]
    for key, resolvers in yaml.SafeLoader.yaml_implicit_resolvers.items()
}
Yaml12Loader.add_implicit_resolver(
    "tag:yaml.org,2002:bool", re.compile(r"^(?:true|True|TRUE|false|False|FALSE)$"),
    list("tTfF"))
Yaml12Loader.add_implicit_resolver(
    "tag:yaml.org,2002:int", re.compile(r"^(?:[-+]?[0-9]+|0o[0-7]+|0x[0-9a-fA-F]+)$"),
    list("-+0123456789"))
Yaml12Loader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"^(?:[-+]?(?:\.[0-9]+|[0-9]+(?:\.[0-9]*)?)(?:[eE][-+]?[0-9]+)?"
               r"|[-+]?\.(?:inf|Inf|INF)|\.(?:nan|NaN|NAN))$"),
    list("-+.0123456789"))


def _int_1_2(loader, node):
    text = loader.construct_scalar(node)
    if text.startswith("0o"):
        return int(text[2:], 8)
    if text.startswith("0x"):
        return int(text[2:], 16)
    return int(text)


def _float_1_2(loader, node):
    text = loader.construct_scalar(node).lower()
    if text.lstrip("+-") == ".inf":
        return float("-inf") if text.startswith("-") else float("inf")
    if text == ".nan":
        return float("nan")
    return float(text)


Yaml12Loader.add_constructor("tag:yaml.org,2002:int", _int_1_2)
Yaml12Loader.add_constructor("tag:yaml.org,2002:float", _float_1_2)


def property_nodes(node, path="$"):
    """Yields (path, schema) for every property, list item and definition of the schema."""
    if not isinstance(node, dict):
        return
    for key, child in node.get("properties", {}).items():
        yield f"{path}.{key}", child
        yield from property_nodes(child, f"{path}.{key}")
    if isinstance(node.get("items"), dict):
        yield f"{path}[]", node["items"]
        yield from property_nodes(node["items"], f"{path}[]")
    for key, child in node.get("definitions", {}).items():
        yield f"#/definitions/{key}", child
        yield from property_nodes(child, f"#/definitions/{key}")
    for keyword in ("oneOf", "anyOf", "allOf"):
        for i, branch in enumerate(node.get(keyword, [])):
            yield from property_nodes(branch, f"{path}/{keyword}/{i}")


def check_schema(schema):
    problems = []
    try:
        jsonschema.Draft7Validator.check_schema(schema)
    except jsonschema.SchemaError as error:
        problems.append(f"not a valid Draft 7 schema: {error.message}")
    for path, node in property_nodes(schema):
        description = node.get("description")
        if not isinstance(description, str) or not description.strip():
            problems.append(f"{path}: no description")
        elif not UNIT.search(description):
            problems.append(f"{path}: description names no unit: {description!r}")
        if "default" in node:
            standalone = dict(node, definitions=schema.get("definitions", {}))
            for error in jsonschema.Draft7Validator(standalone).iter_errors(node["default"]):
                problems.append(f"{path}: default {node['default']!r} is invalid: {error.message}")
    if schema.get("properties", {}).get("name", {}).get("type") != "string":
        problems.append("$.name: expected a string property")
    return problems


def validate_file(validator, path):
    try:
        with open(path, encoding="utf-8") as stream:
            document = yaml.load(stream, Loader=Yaml12Loader)
    except yaml.YAMLError as error:
        return [f"{path}: YAML error: {error}"]
    return [f"{path}: {'.'.join(str(p) for p in error.absolute_path) or '(document)'}: "
            f"{error.message}" for error in validator.iter_errors(document)]


def check_resolved(binary, validator, path):
    """`mrsim check` on a bundled scenario prints the resolved scenario on stdout."""
    run = subprocess.run([str(binary), "check", str(path)], capture_output=True, text=True,
                         timeout=120, check=False)
    if run.returncode != 0:
        return [f"{path}: mrsim check exited with {run.returncode}: {run.stderr.strip()}"]
    try:
        as_yaml_1_1 = yaml.safe_load(run.stdout)
        as_yaml_1_2 = yaml.load(run.stdout, Loader=Yaml12Loader)
    except yaml.YAMLError as error:
        return [f"{path}: resolved scenario is not YAML: {error}"]
    problems = [f"{path} (resolved): {'.'.join(str(p) for p in e.absolute_path)}: {e.message}"
                for e in validator.iter_errors(as_yaml_1_1)]
    if as_yaml_1_1 != as_yaml_1_2:
        problems.append(f"{path} (resolved): YAML 1.1 and 1.2 readers disagree")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--binary")
    parser.add_argument("--source", required=True)
    parser.add_argument("--shared")
    args = parser.parse_args()
    source = pathlib.Path(args.source)

    with open(source / "schemas" / "scenario.schema.json", encoding="utf-8") as stream:
        schema = json.load(stream)
    problems = check_schema(schema)
    validator = jsonschema.Draft7Validator(schema)

    files = sorted((source / "scenarios").glob("*.yaml")) + \
        sorted((source / "tests" / "scenario" / "good").glob("*.yaml"))
    if not files:
        problems.append("no scenario to validate (scenarios/*.yaml, tests/scenario/good/*.yaml)")
    for path in files:
        problems += validate_file(validator, path)
    binary = pathlib.Path(args.binary) if args.binary else None
    if binary and binary.is_file():
        for path in sorted((source / "scenarios").glob("*.yaml")):
            problems += check_resolved(binary, validator, path)
    else:
        print("mrsim binary absent: resolved scenarios not checked")

    for problem in problems:
        print(problem, file=sys.stderr)
    print(f"schema checked, {len(files)} scenario(s) validated, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
