"""The figures of one `rtsim sim` run under today's names, for scripts/same-answers.

  same_answers.py NAME STATS_JSON          prints one line: NAME, cycles, and every figure
  same_answers.py --compare BEFORE NOW     exit 1 if a figure of BEFORE differs or is gone in NOW

A line holds the run's stats.json flattened to dotted names (host timings left out), each old
name mapped to its new one, so that answers recorded before a rename compare with those after:
a figure that exists on both sides must be equal; one that only the new build reports is new.
"""
import json
import re
import sys

# Old name -> new name, first match wins (the cache levels became mem.NAME.*: issue 61).
RENAMES = [
    (r"^(.*\.)?l1_(accesses|hits|misses|hit_rate|miss_rate)$", r"\1mem.l1.\2"),
    (r"^(.*\.)?l2_(accesses|hits|misses|hit_rate|miss_rate)$", r"\1mem.l2.\2"),
    (r"^counters\.(rt\d+)\.l1\.(.*)$", r"counters.mem.l1.\1.\2"),
    (r"^counters\.l2\.(.*)$", r"counters.mem.l2.\1"),
    (r"^counters\.xbar\.(.*)$", r"counters.mem.l2.xbar.\1"),
    (r"^config\.rt\.l1\.(.*)$", r"config.memory.l1.\1"),
    (r"^config\.l2\.(.*)$", r"config.memory.l2.\1"),
    (r"^config\.xbar\.(latency|bytes_per_cycle)$", r"config.memory.l1.link_\1"),
]


def new_name(key):
    for old, new in RENAMES:
        if re.match(old, key):
            return re.sub(old, new, key)
    return key


def flatten(node, prefix, out):
    if isinstance(node, dict):
        for k, v in node.items():
            flatten(v, f"{prefix}.{k}" if prefix else k, out)
    elif isinstance(node, list):
        for i, v in enumerate(node):
            flatten(v, f"{prefix}.{i}", out)
    else:
        out[new_name(prefix)] = node


def line(name, path):
    stats = json.load(open(path))
    stats.pop("host", None)
    figures = {}
    flatten(stats, "", figures)
    return json.dumps({"name": name, "cycles": stats["summary"]["cycles"], "figures": figures},
                      sort_keys=True)


def compare(before_path, now_path):
    now = {}
    for text in open(now_path):
        run = json.loads(text)
        now[run["name"]] = run
    failed = 0
    for text in open(before_path):
        run = json.loads(text)
        other = now.get(run["name"])
        if other is None:
            print(f"{run['name']}: not run now")
            failed = 1
            continue
        changed = [k for k, v in run["figures"].items() if other["figures"].get(k, v) != v]
        gone = [k for k in run["figures"] if k not in other["figures"]]
        if changed or gone:
            failed = 1
            print(f"{run['name']}: {run['cycles']} -> {other['cycles']} cycles; "
                  f"{len(changed)} figures differ, {len(gone)} gone")
            for k in (changed + gone)[:8]:
                print(f"  {k}: {run['figures'][k]} -> {other['figures'].get(k, '(gone)')}")
        else:
            print(f"{run['name']}: same ({other['cycles']} cycles, {len(run['figures'])} figures)")
    return failed


if __name__ == "__main__":
    if sys.argv[1] == "--compare":
        sys.exit(compare(sys.argv[2], sys.argv[3]))
    print(line(sys.argv[1], sys.argv[2]))
