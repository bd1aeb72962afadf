"""The figures of one `rtsim sim` run under today's names, for scripts/same-answers.

  same_answers.py NAME STATS_JSON          prints one line: NAME, cycles, and every figure
  same_answers.py --compare BEFORE NOW     exit 1 if a figure of BEFORE differs or is gone in NOW

A line holds the run's stats.json flattened to dotted names (host timings left out). The
comparison maps each old name to its new one on both sides, so that answers recorded before a
rename compare with those after: a figure that exists on both sides must be equal; one that
only the new build reports is new.
"""
import json
import os
import re
import sys

# Old name -> new name, first match wins (the cache levels became mem.NAME.*: issue 61).
RENAMES = [
    (r"^stats\.(counters|derived)\.(.*\.)l1_(accesses|hits|misses|hit_rate|miss_rate)$",
     r"stats.\1.\2mem.l1.\3"),
    (r"^stats\.(counters|derived)\.(.*\.)l2_(accesses|hits|misses|hit_rate|miss_rate)$",
     r"stats.\1.\2mem.l2.\3"),
    (r"^stats\.(counters|derived)\.(rt\d+)\.l1\.(.*)$", r"stats.\1.mem.l1.\2.\3"),
    (r"^stats\.(counters|derived)\.l2\.(.*)$", r"stats.\1.mem.l2.\2"),
    (r"^stats\.(counters|derived)\.xbar\.(.*)$", r"stats.\1.mem.l2.xbar.\2"),
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
        out[prefix] = node


def line(name, path):
    stats = json.load(open(path))
    stats.pop("host", None)
    figures = {}
    flatten(stats, "", figures)
    return json.dumps({"name": name, "cycles": stats["summary"]["cycles"], "figures": figures},
                      sort_keys=True)


def compare(before_path, now_path):
    def read(text):
        run = json.loads(text)
        # A scene path through a worktree's "../shared" names the same file from any worktree.
        run["figures"] = {new_name(k): os.path.normpath(v) if k == "input.scene" else v
                          for k, v in run["figures"].items()}
        return run

    now = {}
    for text in open(now_path):
        run = read(text)
        now[run["name"]] = run
    failed = 0
    for text in open(before_path):
        run = read(text)
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
