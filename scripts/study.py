"""What the study scripts (scripts/dram-study, scripts/treelet-study) share: running rtsim and
reading a run's stats.json. They run build/bin/rtsim, or the binary $RTSIM names (a copy keeps
a long study apart from rebuilds)."""
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RTSIM = os.environ.get("RTSIM") or os.path.join(ROOT, "build", "bin", "rtsim")
SCENES_DIR = os.path.join(ROOT, "..", "shared", "scenes")


def run(tool, cmd):
    """Runs cmd; on failure exits naming the tool, the command and its stderr."""
    done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        sys.exit(f"{tool}: {' '.join(cmd)} failed ({done.returncode}):\n{done.stderr}")


def simulate(tool, stream, config, sets, folder, extra=()):
    """rtsim sim of a stream on a config with --set overrides into folder; its stats.json."""
    cmd = [RTSIM, "sim", stream, "--config", config, "-o", folder, "-q", *extra]
    for s in sets:
        cmd += ["--set", s]
    run(tool, cmd)
    with open(os.path.join(folder, "stats.json")) as f:
        return json.load(f)
