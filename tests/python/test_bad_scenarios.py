#!/usr/bin/python3
"""Every tests/scenario/bad/*.yaml makes `mrsim check FILE` exit with code 2 (bad input)
and print, on stderr, the text its first line announces ("# expect: <text>").

Run by ctest as: /usr/bin/python3 THIS --binary MRSIM --source REPO --shared SHARED
Exit 0: pass; 1: failure (the reasons are printed); 77: skipped (no mrsim binary).
"""
import argparse
import pathlib
import subprocess
import sys

EXPECT = "# expect: "
EXIT_BAD_INPUT = 2


def expectation(path):
    with open(path, encoding="utf-8") as stream:
        first = stream.readline().rstrip("\n")
    return first[len(EXPECT):] if first.startswith(EXPECT) else None


def check_one(binary, path):
    expected = expectation(path)
    if not expected:
        return [f"{path.name}: first line must be '{EXPECT}<text>'"]
    try:
        run = subprocess.run([str(binary), "check", str(path)], capture_output=True, text=True,
                             timeout=60, check=False)
    except subprocess.TimeoutExpired:
        return [f"{path.name}: mrsim check did not finish within 60 s"]
    problems = []
    if run.returncode != EXIT_BAD_INPUT:
        problems.append(f"{path.name}: exit code {run.returncode}, expected {EXIT_BAD_INPUT}")
    if expected not in run.stderr:
        problems.append(f"{path.name}: stderr does not contain {expected!r}:\n{run.stderr}")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--binary", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--shared")
    args = parser.parse_args()
    binary = pathlib.Path(args.binary)
    if not binary.is_file():
        print(f"skipped: no mrsim binary at {binary}")
        return 77

    corpus = sorted((pathlib.Path(args.source) / "tests" / "scenario" / "bad").glob("*.yaml"))
    problems = [] if len(corpus) >= 20 else [f"only {len(corpus)} bad scenarios, expected >= 20"]
    for path in corpus:
        problems += check_one(binary, path)

    for problem in problems:
        print(problem, file=sys.stderr)
    print(f"{len(corpus)} bad scenario(s) checked, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
