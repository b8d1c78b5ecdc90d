"""What the measuring tools of tools/ share (tools/bench, tools/kernel_costs,
tools/speed_accuracy, tools/stability): where the checkout and the scenes are, running one
`--bench` command for its JSON report, and drawing a chart with a script of tools/lib."""
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


def draw_chart(tool, script, csv_path, png_path, extra_args=()):
    """Draws a chart with tools/lib/SCRIPT CSV PNG EXTRA_ARGS; False after saying why not.
    Debian's python3-matplotlib belongs to /usr/bin/python3, which need not be the python3
    running this tool (a pyenv or a virtual environment first on PATH), so that one is
    tried too."""
    result = None
    for python in dict.fromkeys((sys.executable, "/usr/bin/python3")):
        if not pathlib.Path(python).exists():
            continue
        result = subprocess.run([python, str(ROOT / "tools" / "lib" / script), str(csv_path),
                                 str(png_path), *extra_args], capture_output=True, text=True)
        if result.returncode == 0:
            return True
        if result.returncode != 3:  # 3: no matplotlib for this python, try the next
            break
    print(f"{tool}: no chart: {result.stderr.strip() if result else 'no python'}", file=sys.stderr)
    return False
