# Writes a.png (4x2 RGBA, pixel i = (10i, 20i, 30i, 255)) and b.png, equal but for two pixels:
# (1, 0) red +5 and (2, 1) blue -100 and alpha -1 — the counts the compare test expects follow from
# these two edits. Plain zlib + struct, so the test does not depend on the code under test.
# frame.png: the 8x4 frame draw_test.cpp's display dump shows (sprite (1, 1) .. (5, 3), colour
# (10, 20, 30), everything else black, opaque); frame_off.png: the same with pixel (0, 0) = (0, 0, 1).
import struct, sys, zlib

def png(path, px, w, h):
    raw = b''.join(b'\0' + bytes(sum((px[y * w + x] for x in range(w)), ())) for y in range(h))
    def chunk(t, d):
        return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
    data = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 6, 0, 0, 0))
    data += chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b'')
    open(path, 'wb').write(data)

out = sys.argv[1]
a = [(10 * i, 20 * i, 30 * i, 255) for i in range(8)]
b = list(a)
b[1] = (15, 20, 30, 255)
b[6] = (60, 120, 80, 254)
png(out + '/a.png', a, 4, 2)
png(out + '/b.png', b, 4, 2)
f = [(10, 20, 30, 255) if 1 <= x < 5 and 1 <= y < 3 else (0, 0, 0, 255) for y in range(4) for x in range(8)]
png(out + '/frame.png', f, 8, 4)
f[0] = (0, 0, 1, 255)
png(out + '/frame_off.png', f, 8, 4)
