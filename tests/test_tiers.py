#!/usr/bin/python3
"""The test tiers (tests/CMakeLists.txt): every test is labelled `full`, the quick tier is a
proper part of it, and every name after SLOW in a test folder's CMakeLists.txt is still a test
(a renamed slow test would otherwise drop into the quick tier unseen).

  tests/test_tiers.py BUILD_DIR            the check (ctest runs it as test_tiers); exit 1 on a fault
  tests/test_tiers.py BUILD_DIR --costs    after a full `ctest -j2`: tests whose measured time
                                           (Testing/Temporary/CTestCostData.txt) puts them in the
                                           other tier than their label, for moving by hand
"""
import fnmatch
import json
import os
import subprocess
import sys

SLOW_SECONDS = 1.0  # a test at least this long (average of ctest's runs) belongs in `full` only


def tests_and_labels(build):
    out = subprocess.run(["ctest", "--show-only=json-v1"], cwd=build, check=True,
                         capture_output=True, text=True).stdout
    labels = {}
    for test in json.loads(out)["tests"]:
        props = {p["name"]: p["value"] for p in test.get("properties", [])}
        labels[test["name"]] = set(props.get("LABELS", []))
    return labels


def slow_patterns(build):
    folder = os.path.join(build, "tests", "tiers")
    patterns = []
    for name in sorted(os.listdir(folder)):
        with open(os.path.join(folder, name)) as f:
            patterns += [(name[:-len(".slow")], line.strip()) for line in f if line.strip()]
    return patterns


def gtest_match(name, pattern):
    # gtest filters know * and ?; a parameterised test's ctest name carries its value after '/'.
    return fnmatch.fnmatchcase(name, pattern.replace("[", "[[]"))


def faults(labels, patterns):
    found = []
    for name, tags in sorted(labels.items()):
        if "full" not in tags:
            found.append(f"{name}: not labelled full (labels: {sorted(tags) or 'none'})")
        if tags - {"quick", "full"}:
            found.append(f"{name}: unknown labels {sorted(tags - {'quick', 'full'})}")
    quick = [n for n, tags in labels.items() if "quick" in tags]
    if not quick or len(quick) == len(labels):
        found.append(f"the quick tier has {len(quick)} of {len(labels)} tests: not a proper part")
    slow = [n for n, tags in labels.items() if "quick" not in tags]
    for binary, pattern in patterns:
        if not any(gtest_match(n, pattern) for n in slow):
            found.append(f"{binary}: SLOW {pattern} names no test of the full-only tier")
    return found


def cost_advice(build, labels):
    path = os.path.join(build, "Testing", "Temporary", "CTestCostData.txt")
    if not os.path.exists(path):
        print(f"{path}: missing; run `ctest -j2` in {build} first", file=sys.stderr)
        return 2
    for line in open(path):
        parts = line.split()
        if len(parts) != 3 or parts[0] not in labels:
            continue
        seconds, quick = float(parts[2]), "quick" in labels[parts[0]]
        if quick and seconds >= SLOW_SECONDS:
            print(f"{parts[0]}: {seconds:.2f} s, labelled quick: add it after SLOW")
        elif not quick and seconds < SLOW_SECONDS and "fuzz" not in parts[0]:
            print(f"{parts[0]}: {seconds:.2f} s, labelled full only: could be quick")
    return 0


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    build = sys.argv[1]
    labels = tests_and_labels(build)
    if sys.argv[2:] == ["--costs"]:
        return cost_advice(build, labels)
    found = faults(labels, slow_patterns(build))
    for fault in found:
        print("test tiers:", fault)
    quick = sum("quick" in tags for tags in labels.values())
    print(f"test tiers: {quick} quick, {len(labels) - quick} full only, {len(found)} faults")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
