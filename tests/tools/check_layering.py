#!/usr/bin/env python3
"""Checks the layering of host/: every #include of a project header points down the stack
of folders (docs/design.md), only host/window/ includes GLFW, and, given binaries, that the
headless ones do not load GLFW while Raytracer does (so the check cannot pass vacuously).

usage: check_layering.py SOURCE_DIR [--headless BINARY...] [--windowed BINARY...]
Exit status 0 when the layering holds, 1 naming each violation, 2 on usage errors.
"""
import argparse
import pathlib
import re
import subprocess
import sys

# Each folder may include its own headers and those of the folders listed for it.
ALLOWED = {
    "base": set(),
    "scene": {"base"},
    "model": {"base", "scene"},
    "gpu": {"base"},
    "packing": {"base", "scene"},
    "render": {"base", "scene", "gpu", "packing"},
    "cli": {"base", "scene", "model", "gpu", "packing", "render"},
    "window": {"base", "scene", "model", "gpu", "packing", "render", "cli", "compare"},
    "reference": {"base", "scene"},
    "compare": {"base", "scene", "reference"},
    # main.cpp, bench.*, batch.*
    ".": {"base", "scene", "model", "gpu", "packing", "render", "cli", "window", "reference", "compare"},
}
INCLUDE = re.compile(r'^\s*#\s*include\s+["<]([^">]+)[">]', re.M)


def include_problems(host: pathlib.Path) -> list[str]:
    problems = []
    for path in sorted(host.rglob("*")):
        if path.suffix not in (".h", ".cpp"):
            continue
        folder = path.parent.relative_to(host).as_posix()
        if folder not in ALLOWED:
            problems.append(f"{path}: host/{folder}/ is not a known layer")
            continue
        for included in INCLUDE.findall(path.read_text()):
            if included.startswith("GLFW/") and folder != "window":
                problems.append(f"{path}: includes {included}; only host/window/ may use GLFW")
            top = included.split("/")[0]
            if top in ALLOWED and top != "." and "/" in included:
                if top != folder and top not in ALLOWED[folder]:
                    problems.append(f"{path}: includes {included}, above host/{folder}/")
    return problems


def links_glfw(binary: str) -> bool:
    output = subprocess.run(["ldd", binary], capture_output=True, text=True, check=True).stdout
    return "libglfw" in output


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("source_dir", type=pathlib.Path)
    parser.add_argument("--headless", nargs="*", default=[], help="binaries that must not load GLFW")
    parser.add_argument("--windowed", nargs="*", default=[], help="binaries that must load GLFW")
    args = parser.parse_args()
    host = args.source_dir / "host"
    if not host.is_dir():
        parser.error(f"{host} is not a folder")
    problems = include_problems(host)
    problems += [f"{b}: loads GLFW but renders headless only" for b in args.headless if links_glfw(b)]
    problems += [f"{b}: does not load GLFW (is ldd telling the truth?)" for b in args.windowed
                 if not links_glfw(b)]
    for problem in problems:
        print(problem)
    checked = len(args.headless) + len(args.windowed)
    print(f"check_layering: host/ includes and {checked} binaries checked, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
