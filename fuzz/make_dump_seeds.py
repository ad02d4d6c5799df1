# fuzz/make_dump_seeds.py — writes the draw_* seeds of fuzz/corpus/dump_reader: a new-layout dump with a
# 16-byte version-7 state (not loaded), 8 KiB privileged registers (PMODE.EN1, DISPFB1 FBW 1, DISPLAY1
# 8x4), one PATH2 transfer of A+D writes (register values from the GS manual's bit layouts), a vsync.
# The state_* seeds hold whole state blobs (xz-compressed): PCSX2's version-8 and version-9 layouts and
# gsdot3's older version 8 (docs/dumps.md "The state blob").
# Run from the repository root: python3 fuzz/make_dump_seeds.py
import lzma
import struct
def ad(writes):
    q = struct.pack('<QQ', len(writes) | (1 << 15) | (1 << 60), 0xE)  # NLOOP, EOP, FLG PACKED, NREG 1; REGS A+D
    for a, v in writes: q += struct.pack('<QQ', v & (2**64 - 1), a)
    return q
def dump(gif, state=struct.pack('<I', 7) + bytes(12)):
    hdr = struct.pack('<9I', state[0], len(state), 36, 0, 0, 0, 0, 36, 0)
    priv = bytearray(8192)
    priv[0:8] = struct.pack('<Q', 1)
    priv[0x70:0x78] = struct.pack('<Q', 1 << 9)
    priv[0x80:0x88] = struct.pack('<Q', (7 << 32) | (3 << 44))
    out = struct.pack('<II', 0xFFFFFFFF, 36) + hdr + state + bytes(priv)
    out += bytes([0, 1]) + struct.pack('<I', len(gif)) + gif + bytes([1, 0])
    return out
env = [(0x1A, 1), (0x46, 1), (0x4C, 1 << 16), (0x40, (63 << 16) | (63 << 48)), (0x4E, 8), (0x47, (1 << 16) | (2 << 17))]
rgbaq = lambda r, g, b, a: r | g << 8 | b << 16 | a << 24 | (0x3F800000 << 32)
xyz = lambda x, y, z=0: x | y << 16 | z << 32
sprite = env + [(0, 6), (1, rgbaq(10, 20, 30, 40)), (5, xyz(16, 16, 5)), (5, xyz(80, 48, 5))]
tri = env + [(0, 4 | 8), (1, rgbaq(255, 0, 0, 128)), (5, xyz(0, 0, 9)), (1, rgbaq(0, 255, 0, 128)), (5, xyz(128, 8, 9)),
             (1, rgbaq(0, 0, 255, 128)), (5, xyz(8, 64, 9)), (0xD, xyz(120, 60, 9)), (5, xyz(60, 70, 9))]
tex0 = 1024 | 1 << 14 | 0x13 << 20 | 3 << 26 | 3 << 30 | 1 << 35 | 2048 << 37 | 1 << 61
textured = env + [(0x06, tex0), (0x14, 1 << 5), (0x08, 1 | 1 << 2), (0, 6 | 1 << 4 | 1 << 8 | 1 << 6), (0x42, 1 << 2 | 1 << 6),
                  (3, 8 | 8 << 16), (5, xyz(0, 0)), (3, 136 | 136 << 16), (5, xyz(128, 64))]
fog = env + [(0, 6 | 1 << 5), (5, xyz(0, 0)), (5, xyz(32, 32))]
# Perspective texturing (PRIM.FST = 0, Q = 1, 1/2, 1/4 at the three vertices; gs_arith/perspective.hpp).
f32 = lambda x: struct.unpack('<I', struct.pack('<f', x))[0]
stq = lambda s, t, q: [(1, 0x80808080 | f32(q) << 32), (2, f32(s * q) | f32(t * q) << 32)]
perspective = env + [(0x06, tex0), (0x14, 1 << 9), (0x08, 1 | 1 << 2), (0, 3 | 1 << 4)] + \
    stq(0.1, 0.1, 1.0) + [(5, xyz(0, 0))] + stq(0.9, 0.2, 0.5) + [(5, xyz(900, 40))] + stq(0.3, 0.9, 0.25) + [(5, xyz(60, 900))]
for name, w in [('draw_sprite', sprite), ('draw_strip_xyz3', tri), ('draw_textured_clut', textured), ('draw_fog_skipped', fog),
                ('draw_perspective', perspective)]:
    open('fuzz/corpus/dump_reader/' + name + '.gs', 'wb').write(dump(ad(w)))
# The reader's PCSX2 leniencies (issue 29), one seed each from the draw_sprite dump: the last packet
# (the vsync) cut, a transfer path byte 4, a screenshot size that is not w x h x 4, an A+D write to 0x7F.
base = dump(ad(sprite))
open('fuzz/corpus/dump_reader/lenient_truncated_last.gs', 'wb').write(base[:-1])
at = len(base) - 2 - 6 - len(ad(sprite))  # the transfer's type byte
open('fuzz/corpus/dump_reader/lenient_path4.gs', 'wb').write(base[:at + 1] + bytes([4]) + base[at + 2:])
open('fuzz/corpus/dump_reader/lenient_screenshot.gs', 'wb').write(base[:40] + struct.pack('<I', 12) + base[44:])
open('fuzz/corpus/dump_reader/lenient_unused_register.gs', 'wb').write(dump(ad(sprite + [(0x7F, 1)])))
# Whole states, memory zero, PRMODECONT.AC = 1 (byte 12), Q = 1.0f: (name, version, size, Q's offset).
for name, version, size, q in [('state_v8_pcsx2', 8, 4194752, 4194748), ('state_v9_pcsx2', 9, 4194813, 4194809),
                               ('state_v8_gsdot3_old', 8, 4194760, 4194756)]:
    st = bytearray(size)
    st[0], st[12] = version, 1
    st[q:q + 4] = struct.pack('<f', 1.0)
    open('fuzz/corpus/dump_reader/' + name + '.gs.xz', 'wb').write(lzma.compress(dump(ad(sprite), bytes(st))))
