#!/usr/bin/env python3
"""png_to_bmp.py IN.png OUT.bmp [X Y RRGGBB]: an 8-bit RGB PNG (as gsdot3 writes it: not interlaced)
to a 24-bit bottom-up BMP, with one pixel optionally replaced; or `png_to_bmp.py --blank W H OUT.bmp`
for a black BMP of another size. Standard library only (zlib, struct), so the BMP is made without
the code under test."""
import os
import struct
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from png_read import read_png  # noqa: E402


def read_png_rgb(path):
    rows = read_png(path)
    return len(rows[0]) if rows else 0, len(rows), [bytearray(b for px in row for b in px) for row in rows]


def write_bmp(path, width, height, rows):
    pad = (4 - 3 * width % 4) % 4
    pixels = b"".join(bytes(sum(([r[3 * x + 2], r[3 * x + 1], r[3 * x]] for x in range(width)), [])) + b"\0" * pad
                      for r in reversed(rows))
    header = struct.pack("<2sIHHI", b"BM", 54 + len(pixels), 0, 0, 54)
    info = struct.pack("<IiiHHIIiiII", 40, width, height, 1, 24, 0, len(pixels), 2835, 2835, 0, 0)
    open(path, "wb").write(header + info + pixels)


if sys.argv[1] == "--blank":
    w, h = int(sys.argv[2]), int(sys.argv[3])
    write_bmp(sys.argv[4], w, h, [bytearray(3 * w) for _ in range(h)])
else:
    w, h, rows = read_png_rgb(sys.argv[1])
    if len(sys.argv) > 3:
        x, y, rgb = int(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5], 16)
        rows[y][3 * x:3 * x + 3] = bytes([rgb >> 16, rgb >> 8 & 255, rgb & 255])
    write_bmp(sys.argv[2], w, h, rows)
