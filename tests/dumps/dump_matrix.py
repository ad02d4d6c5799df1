#!/usr/bin/env python3
"""Writes the dumps of issue 29's matrix with `gsdot3 dump` / `gsdot3 probe` and checks every one with
pcsx2_check.py (the independent reader): the three methods with 1 to 4 lights (NTSC, raw), PAL and
VESA, .gs.xz, .gs.zst and an upper-case .GS.ZST, a 64² height map, a 1024² one (streamed) for each
method, the probe. Every dump must
pass within PCSX2's limits and the 1 MiB packet bound. Then the counter-check: the 4-light four-pass
dump written as one unsplit transfer (--max-packet 1 GiB, what gsdot3 wrote before issue 29) must FAIL
the check on PCSX2's 9 MiB path buffer. Usage: dump_matrix.py GSDOT3 OUT_DIR
"""
import os
import struct
import subprocess
import sys
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pcsx2_check  # noqa: E402

LIGHTS = ['-2.2,1.4,2.2:109820', '2.6,-0.2,0.4:1038B0', '0,2.5,1.5:604020', '-1,-2,2:202060']


def grey_png(path, n):
    """An n x n 8-bit grey PNG: a smooth bump pattern (PNG: signature, IHDR, IDAT, IEND; filter 0)."""
    rows = b''.join(b'\x00' + bytes((((x * 7) ^ (y * 5)) >> 2) & 0xFF for x in range(n)) for y in range(n))
    def chunk(tag, data):
        return struct.pack('>I', len(data)) + tag + data + struct.pack('>I', zlib.crc32(tag + data) & 0xFFFFFFFF)
    ihdr = struct.pack('>IIBBBBB', n, n, 8, 0, 0, 0, 0)
    open(path, 'wb').write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', ihdr) + chunk(b'IDAT', zlib.compress(rows)) + chunk(b'IEND', b''))


def main(gsdot3, out):
    os.makedirs(out, exist_ok=True)
    runs = []  # (file, video, command)
    for method in ('two-pass', 'four-pass', 'baseline', 'three-pass', 'gouraud'):
        for n in range(1, 5):
            f = os.path.join(out, '%s-%dl.gs' % (method, n))
            runs.append((f, 'ntsc', ['dump', '--method', method] + sum((['--light', l] for l in LIGHTS[:n]), [])))
        runs.append((os.path.join(out, '%s-4l-pal.gs' % method), 'pal',
                     ['dump', '--method', method, '--video', 'pal'] + sum((['--light', l] for l in LIGHTS), [])))
    runs.append((os.path.join(out, 'two-pass-vesa.gs'), 'vesa', ['dump', '--method', 'two-pass', '--video', 'vesa']))
    runs.append((os.path.join(out, 'four-pass-2l.gs.xz'), 'ntsc', ['dump', '--method', 'four-pass']))
    runs.append((os.path.join(out, 'baseline-2l.gs.zst'), 'ntsc', ['dump', '--method', 'baseline']))
    runs.append((os.path.join(out, 'two-pass-2l-upper.GS.ZST'), 'pal', ['dump', '--method', 'two-pass', '--video', 'pal']))
    # A 64x64 height map (the upload cut at any qword) and a 1024x1024 one, whose textures do not fit
    # beside the frame buffers and are streamed per pass in pieces (pipeline/texture_stream.hpp).
    for n, methods in ((64, ('four-pass',)), (1024, ('two-pass', 'four-pass', 'baseline'))):
        grey_png(os.path.join(out, 'height%d.png' % n), n)
        for method in methods:
            runs.append((os.path.join(out, '%s-4l-map%d.gs' % (method, n)), 'ntsc',
                         ['dump', '--method', method, '--height-map', os.path.join(out, 'height%d.png' % n)] +
                         sum((['--light', l] for l in LIGHTS), [])))
    runs.append((os.path.join(out, 'probe.gs'), 'ntsc', ['probe']))
    bad = 0
    for f, video, cmd in runs:
        subprocess.run([gsdot3] + cmd + ['--out', f], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        if f.endswith('.GS.ZST') and open(f, 'rb').read(4) != b'\x28\xb5\x2f\xfd':
            print('FAIL %s: the upper-case .ZST extension did not compress with zstd' % f)
            bad += 1
            continue
        try:
            print(pcsx2_check.check(f, video, pcsx2_check.MIB))
        except pcsx2_check.Fail as e:
            print('FAIL %s: %s' % (f, e))
            bad += 1
    # The counter-check: one unsplit transfer of the 4-light four-pass frame.
    f = os.path.join(out, 'four-pass-4l-unsplit.gs')
    subprocess.run([gsdot3, 'dump', '--method', 'four-pass', '--max-packet', str(1 << 30), '--out', f] +
                   sum((['--light', l] for l in LIGHTS), []), check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        print('FAIL %s: the unsplit dump passed: %s' % (f, pcsx2_check.check(f, 'ntsc')))
        bad += 1
    except pcsx2_check.Fail as e:
        ok = "exceeds PCSX2's 9 MiB GIF path buffer" in str(e)
        print('%s %s: refused as expected: %s' % ('OK' if ok else 'FAIL', os.path.basename(f), e))
        bad += 0 if ok else 1
    print('%d of %d dumps failed' % (bad, len(runs) + 1))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1], sys.argv[2]))
