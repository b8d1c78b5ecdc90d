#!/usr/bin/env python3
"""Write a small benchmark scene: N mirror spheres and M triangles in a row, one light.

    python3 tools/make_row_scene.py SPHERES TRIANGLES [-o FILE]   (default: stdout)

The scenes "sNtM" of docs/performance.md (small scenes' spheres baked into the kernel),
which measure the brute-force path at chosen counts: spheres of radius 0.45 one unit
apart at z = -5 (ks 0.3, so every one reflects), triangles one unit wide at z = -5 and -6
in turn below them, one white light above the eye. Deterministic, standard library only.
"""

import argparse
import sys


def sphere(i, n):
    x = (i - (n - 1) / 2) * 1.0
    return (f"sphere\npos: {x} {(i % 3) - 1} -5\nrad: 0.45\n"
            "dif: 0.5 0.2 0.2\nspe: 0.3 0.3 0.3\nshi: 20\n")


def triangle(i, n):
    x = (i - (n - 1) / 2) * 1.0
    z = -5 - (i % 2)
    text = "triangle\n"
    for cx, cy in ((x - 0.5, -1.5), (x + 0.5, -1.5), (x, -0.5)):
        text += f"pos: {cx} {cy} {z}\nnor: 0 1 0.5\ndif: 0.2 0.5 0.2\nspe: 0 0 0\nshi: 1\n"
    return text


def row_scene(spheres, triangles):
    body = ("amb: 0.1 0.1 0.1\n" + "".join(sphere(i, spheres) for i in range(spheres)) +
            "".join(triangle(i, triangles) for i in range(triangles)) +
            "light\npos: 0 3 0\ncol: 1 1 1\n")
    return f"{spheres + triangles + 1}\n" + body


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("spheres", type=int)
    parser.add_argument("triangles", type=int)
    parser.add_argument("-o", "--out", help="file to write (default: stdout)")
    args = parser.parse_args()
    if args.spheres < 0 or args.triangles < 0:
        parser.error("counts must be 0 or more")
    text = row_scene(args.spheres, args.triangles)
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
