"""8-bit RGB PNG files with the standard library only: the textures the tests and the gallery
make for their models."""

import pathlib
import struct
import zlib


def png_bytes(width, height, rows):
    """The PNG of rows[y][x] = (r, g, b), top row first, every row unfiltered."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    raw = b"".join(b"\x00" + bytes(value for pixel in row for value in pixel) for row in rows)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def write_png(path, width, height, rows):
    pathlib.Path(path).write_bytes(png_bytes(width, height, rows))
