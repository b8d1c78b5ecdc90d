"""The pixel stories of Raytracer --pixel and reference_render --pixel, compared field by field
(docs/pixel_story.md). Used by tools/pixel_story and the tests.

Rules: hit kinds, indices and source lines, light results and blockers, and how each bounce goes
on must be equal; numbers (t, barycentrics, normals, materials, colours, throughputs) agree when
|gpu - reference| <= TOLERANCE * max(1, |reference|); the final 8-bit colours may differ by at
most LEVELS levels. A GPU bounce whose throughput became 0 ends its tree ("zero-throughput")
where the reference goes on with weight 0: the comparison stops there.
"""
import json
import pathlib

from png_read import read_png

TOLERANCE = 1e-3  # float against double: t, colours and the rest, relative above 1
LEVELS = 1        # 8-bit levels the final colours may differ by (a value on a rounding edge)


def rows(gpu, reference):
    """Every compared field in order: (path, gpu value, reference value, agrees)."""
    out = []

    def add(path, a, b, kind="number"):
        if kind == "exact":
            same = a == b
        elif kind == "levels":
            same = a is not None and b is not None and all(abs(x - y) <= LEVELS for x, y in zip(a, b))
        else:
            same = close(a, b)
        out.append((path, a, b, same))

    add("sample_offset", gpu.get("sample_offset"), reference.get("sample_offset"))
    g_bounces, r_bounces = gpu.get("bounces", []), reference.get("bounces", [])
    for k in range(max(len(g_bounces), len(r_bounces))):
        g = g_bounces[k] if k < len(g_bounces) else {}
        r = r_bounces[k] if k < len(r_bounces) else {}
        p = f"bounces[{k}]"
        add(p + ".ray.origin", dig(g, "ray", "origin"), dig(r, "ray", "origin"))
        add(p + ".ray.direction", dig(g, "ray", "direction"), dig(r, "ray", "direction"))
        for field in ("kind", "index", "line"):
            add(f"{p}.hit.{field}", dig(g, "hit", field), dig(r, "hit", field), "exact")
        for field in ("t", "barycentric"):
            if dig(g, "hit", field) is not None or dig(r, "hit", field) is not None:
                add(f"{p}.hit.{field}", dig(g, "hit", field), dig(r, "hit", field))
        if "normal" in g or "normal" in r:
            add(p + ".normal", g.get("normal"), r.get("normal"))
            for field in ("diffuse", "specular", "shininess"):
                add(f"{p}.material.{field}", dig(g, "material", field), dig(r, "material", field))
            g_lights, r_lights = g.get("lights", []), r.get("lights", [])
            for i in range(min(len(g_lights), len(r_lights))):
                gl, rl, q = g_lights[i], r_lights[i], f"{p}.lights[{i}]"
                add(q + ".line", gl.get("line"), rl.get("line"), "exact")
                add(q + ".result", gl.get("result"), rl.get("result"), "exact")
                if gl.get("result") == "blocked" or rl.get("result") == "blocked":
                    for field in ("kind", "index", "line"):
                        add(f"{q}.blocker.{field}", dig(gl, "blocker", field),
                            dig(rl, "blocker", field), "exact")
                add(q + ".contribution", gl.get("contribution"), rl.get("contribution"))
        for field in ("local", "background"):
            if field in g or field in r:
                add(f"{p}.{field}", g.get(field), r.get(field))
        add(p + ".throughput", g.get("throughput"), r.get("throughput"))
        add(p + ".color", g.get("color"), r.get("color"))
        if g.get("next") == "zero-throughput" and r.get("next") == "reflect":
            out.append((p + ".next", "zero-throughput", "reflect (with weight 0)", True))
            break
        add(p + ".next", g.get("next"), r.get("next"), "exact")
    add("sample_color", gpu.get("sample_color"), reference.get("sample_color"))
    add("pixel_color", gpu.get("pixel_color"), reference.get("pixel_color"))
    add("pixel_8bit", gpu.get("pixel_8bit"), reference.get("pixel_8bit"), "levels")
    return out


def first_difference(gpu, reference):
    """The path of the first field where the stories part, or None."""
    for path, _, _, same in rows(gpu, reference):
        if not same:
            return path
    return None


def close(a, b):
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(close(x, y) for x, y in zip(a, b))
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        return abs(a - b) <= TOLERANCE * max(1.0, abs(b))
    return a == b


def dig(record, *keys):
    for key in keys:
        if not isinstance(record, dict):
            return None
        record = record.get(key)
    return record


def short(value):
    """A value in a table cell: numbers to 7 significant digits."""
    if isinstance(value, float):
        return f"{value:.7g}"
    if isinstance(value, list):
        return "[" + ", ".join(short(v) for v in value) + "]"
    return "-" if value is None else str(value)


def side_by_side(gpu, reference):
    """The table tools/pixel_story prints; the first difference marked with <<<."""
    table = rows(gpu, reference)
    first = next((k for k, row in enumerate(table) if not row[3]), None)
    width = max(len(path) for path, _, _, _ in table)
    lines = [f"{'field':<{width}}  {'gpu':<40}  reference"]
    for k, (path, a, b, same) in enumerate(table):
        mark = "  <<< first difference" if k == first else ("  (differs)" if not same else "")
        lines.append(f"{path:<{width}}  {short(a):<40}  {short(b)}{mark}")
    return "\n".join(lines)


def object_lines(scene_path):
    """{"sphere": [line, ...], "triangle": [...], "light": [...]}: the line of each object's
    keyword in file order, read from the file independently of the renderers' parser."""
    found = {"sphere": [], "triangle": [], "light": []}
    text = pathlib.Path(scene_path).read_bytes().decode("utf-8", "replace")
    for number, line in enumerate(text.splitlines(), start=1):
        for token in line.split():
            if token.lower() in found:
                found[token.lower()].append(number)
    return found


def png_pixel(path, x, y):
    """[r, g, b] of pixel (x, y) of an 8-bit non-interlaced RGB or RGBA PNG."""
    _width, _height, rows = read_png(path)
    return list(rows[y][x])


def load(text, who):
    """One story from a program's stdout."""
    try:
        return json.loads(text)
    except json.JSONDecodeError as error:
        raise RuntimeError(f"{who} printed no JSON story ({error}): {text[:200]!r}") from None
