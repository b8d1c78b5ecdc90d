"""What the benchmark tools of tools/ share (tools/bench, tools/kernel_costs): where the
scenes are, and running one `--bench` command for its JSON report."""
import json
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
SHARED_SCENES = ROOT.parent / "shared" / "scenes"


def classic_scenes():
    # The -b/-c variants differ from their originals only in bytes, not in the picture.
    return [p for p in sorted(SHARED_SCENES.glob("*.scene")) if not p.stem.endswith(("-b", "-c"))]


def run_bench(command, env, timeout):
    """Runs one `--bench` command: (status, report), status "ok", "timeout" or "failed"."""
    try:
        result = subprocess.run(command, capture_output=True, text=True, timeout=timeout, env=env)
    except subprocess.TimeoutExpired:
        return "timeout", None
    lines = result.stdout.strip().splitlines()
    if result.returncode != 0 or not lines:
        tail = result.stderr.strip().splitlines()[-3:]
        print(f"    {pathlib.Path(command[0]).name} failed (exit {result.returncode}): "
              + " | ".join(tail), file=sys.stderr)
        return "failed", None
    try:
        return "ok", json.loads(lines[-1])
    except json.JSONDecodeError:
        print(f"    {pathlib.Path(command[0]).name}: last line is not JSON: {lines[-1][:200]}",
              file=sys.stderr)
        return "failed", None
