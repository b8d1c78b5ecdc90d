#!/usr/bin/env python3
"""image_diff's SSIM against scikit-image's, computed independently.

Usage: ssim_skimage_test.py IMAGE_DIFF RAYTRACER REFERENCE_RENDER CLASSIC_SCENES OUT

skimage.metrics.structural_similarity with gaussian_weights=True, sigma=1.5,
use_sample_covariance=False (Wang et al. 2004), channel_axis=2 (each RGB channel, then
their mean) and data_range 1 (floats) or 255 (bytes) is what tools/reference/ssim.h
promises. Compared on synthetic float images (smooth, noisy, odd sizes) and on a GPU
render against the CPU reference, both as floats and after the kernel's 8-bit rounding.
image_diff prints six decimals, so the two must agree to within 1e-6.
Needs python3-skimage (tools/build/install_deps.sh); under another python3 without it,
the script runs itself again with Debian's.
"""
import os
import pathlib
import re
import struct
import subprocess
import sys

try:
    import numpy as np
    from skimage.metrics import structural_similarity
except ImportError:
    if sys.executable != "/usr/bin/python3" and os.path.exists("/usr/bin/python3"):
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    print("FAIL: python3-skimage is not installed (tools/build/install_deps.sh)")
    sys.exit(1)


def fail(message):
    print(f"FAIL: {message}")
    sys.exit(1)


def write_pfm(path, image):
    """PF header, little-endian floats, rows bottom to top (written here, not by the project)."""
    height, width, _ = image.shape
    with open(path, "wb") as out:
        out.write(f"PF\n{width} {height}\n-1.0\n".encode())
        out.write(np.ascontiguousarray(image[::-1], dtype="<f4").tobytes())


def read_pfm(path):
    data = pathlib.Path(path).read_bytes()
    header = data.split(b"\n", 3)
    if header[0] != b"PF" or float(header[2]) >= 0:
        fail(f"{path}: not a little-endian colour PFM")
    width, height = map(int, header[1].split())
    pixels = np.frombuffer(header[3][:width * height * 12], dtype="<f4")
    return pixels.reshape(height, width, 3)[::-1].astype(np.float32)


def quantize(image):
    """The kernel's rounding, floor(c * 255 + 0.5), in float32 as on the GPU."""
    scaled = image.astype(np.float32) * np.float32(255.0) + np.float32(0.5)
    return np.clip(np.floor(scaled), 0, 255).astype(np.uint8)


def skimage_ssim(a, b, data_range):
    return structural_similarity(a.astype(np.float64), b.astype(np.float64), gaussian_weights=True,
                                 sigma=1.5, use_sample_covariance=False, data_range=data_range,
                                 channel_axis=2)


def image_diff_ssim(image_diff, a_path, b_path):
    result = subprocess.run([image_diff, a_path, b_path, "--min-match", "0"], capture_output=True,
                            text=True)
    if result.returncode != 0:
        fail(f"image_diff {a_path} {b_path} exited {result.returncode}: {result.stderr}")
    found = {kind: float(value) for kind, value in
             re.findall(r"^SSIM (8-bit|float) ([0-9.]+) ", result.stdout, re.MULTILINE)}
    if set(found) != {"8-bit", "float"}:
        fail(f"image_diff printed no SSIM for both: {result.stdout}")
    return found


def check(name, image_diff, a_path, b_path, a, b):
    ours = image_diff_ssim(image_diff, a_path, b_path)
    theirs = {"float": skimage_ssim(a, b, 1.0), "8-bit": skimage_ssim(quantize(a), quantize(b), 255)}
    for kind in ("float", "8-bit"):
        if abs(ours[kind] - theirs[kind]) > 1e-6:
            fail(f"{name} {kind}: image_diff {ours[kind]:.6f}, skimage {theirs[kind]:.9f}")
        print(f"{name} {kind}: image_diff {ours[kind]:.6f}, skimage {theirs[kind]:.9f}")
    return theirs


def main():
    image_diff, raytracer, reference, scenes, out = sys.argv[1:6]
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    random = np.random.default_rng(5)

    # Synthetic: a smooth gradient with texture, against a noisy and a shifted copy.
    for width, height in ((37, 29), (11, 11), (64, 20)):
        y, x = np.mgrid[0:height, 0:width]
        base = np.stack([x / width, y / height, 0.5 + 0.4 * np.sin(x * 0.7 + y * 0.3)], axis=2)
        a = np.clip(base + 0.05 * random.standard_normal(base.shape), 0, 1).astype(np.float32)
        noisy = np.clip(a + 0.08 * random.standard_normal(a.shape), 0, 1).astype(np.float32)
        shifted = np.roll(a, 1, axis=1)
        write_pfm(out / "a.pfm", a)
        for label, b in (("noisy", noisy), ("shifted", shifted)):
            write_pfm(out / f"{label}.pfm", b)
            check(f"{width}x{height} {label}", image_diff, out / "a.pfm", out / f"{label}.pfm", a, b)

    # A render: the GPU at one sample per pixel against the reference at 16 (edges differ).
    scene = pathlib.Path(scenes) / "test2.scene"
    size = ["--width", "96", "--height", "72"]
    for command in ([raytracer, scene, "-o", out / "gpu.pfm"] + size,
                    [reference, scene, "-o", out / "reference.pfm", "--spp", "16"] + size):
        result = subprocess.run(list(map(str, command)), capture_output=True, text=True)
        if result.returncode != 0:
            fail(f"{command[0]} exited {result.returncode}: {result.stderr}")
    gpu, ref = read_pfm(out / "gpu.pfm"), read_pfm(out / "reference.pfm")
    theirs = check("test2 gpu spp1 vs reference spp16", image_diff, out / "gpu.pfm",
                   out / "reference.pfm", gpu, ref)
    if not 0.5 < theirs["float"] < 0.9999:
        fail(f"the render pair is not a useful case: SSIM {theirs['float']}")
    print("OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
