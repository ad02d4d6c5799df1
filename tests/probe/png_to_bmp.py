#!/usr/bin/env python3
"""png_to_bmp.py IN.png OUT.bmp [X Y RRGGBB]: an 8-bit RGB PNG (as gsdot3 writes it: not interlaced)
to a 24-bit bottom-up BMP, with one pixel optionally replaced; or `png_to_bmp.py --blank W H OUT.bmp`
for a black BMP of another size. Standard library only (zlib, struct), so the BMP is made without
the code under test."""
import struct
import sys
import zlib


def read_png_rgb(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    at, idat, width, height = 8, b"", 0, 0
    while at < len(data):
        (n,) = struct.unpack(">I", data[at:at + 4])
        kind, body = data[at + 4:at + 8], data[at + 8:at + 8 + n]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour == 2 and interlace == 0, "only 8-bit RGB, not interlaced"
        elif kind == b"IDAT":
            idat += body
        at += 12 + n
    raw, stride, rows, prev = zlib.decompress(idat), 1 + 3 * width, [], bytearray(3 * width)
    for y in range(height):
        kind, line = raw[y * stride], bytearray(raw[y * stride + 1:(y + 1) * stride])
        for i in range(len(line)):
            a = line[i - 3] if i >= 3 else 0
            b = prev[i]
            c = prev[i - 3] if i >= 3 else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, rows


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
