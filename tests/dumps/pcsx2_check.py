#!/usr/bin/env python3
"""An independent reader of PCSX2 GS dumps (.gs, .gs.xz, .gs.zst), written from PCSX2's behaviour as
read in its sources (facts only): it walks every packet and every GIF tag and checks the limits a
PCSX2 build or a console imposes. Usage: pcsx2_check.py [--video ntsc|pal|vesa] [--max-packet N] FILE...
Exit 0 when every file passes, 1 when one fails (each failure printed as 'FAIL FILE: reason').

Facts used (file and function read):
- GSDumpFile::ReadFile (pcsx2/GS/GSLzma.cpp): u32 CRC or 0xFFFFFFFF; u32 header or state size; the new
  header GSDumpHeader is nine u32 (state_version, state_size, serial_offset, serial_size, crc,
  screenshot_width, screenshot_height, screenshot_offset, screenshot_size); then the state, 8192
  bytes of registers, packets: 0 transfer [path u8][size u32][data], 1 vsync [u8], 2 readFIFO2 [u32],
  3 registers [8192]; any other type fails the read.
- GSState::Defrost (pcsx2/GS/GSState.cpp): refuses a blob whose version exceeds STATE_VERSION (9).
- GSState::Freeze and GetSaveStateSize(int version) (pcsx2/GS/GSState.cpp; version 9 read in the fork
  TJnotJT/pcsx2): each field at its sizeof, from the declarations in GSRegs.h (pack 1: GIFReg* registers
  u64, GIFTag 16 bytes, the GIFReg set 8, GIFPath::reg u32, VM_SIZE 4 MiB), GSVertex.h (RGBAQ, ST, XYZ
  8 bytes; UV and FOG u32) and GSState.h (m_tr: int x, y, w, h, total, start, end; GSVector4i rect 16;
  GIFReg* m_blit, m_pos, m_reg; bool write; float m_q): version 8's blob is
  4 + 15*8 + 2*12*8 + (8 + 8 + 4 + 4 + 8) + 8 + 2*4 + 4 MiB + 4*(16 + 4) + 4 = 4194752 bytes, version 9's
  61 more (4 + 4 + 8 + 8 + 8 + 16 + 4 + 4 + 4 + 1). A blob of another size is read by PCSX2 at offsets
  that are not its own (Defrost checks only that it is not smaller).
- GSDumpReplayerSendPacketToMTGS (pcsx2/GSDumpReplayer.cpp): asserts a transfer is whole qwords and
  copies it whole into the path's buffer, Gif_Path::CopyGSPacketData (pcsx2/Gif_Unit.h), which
  Gif_Unit's constructor sizes 9 MiB; path bytes 1, 2, 3 (PATH2, PATH3, PATH1 in new dumps: the
  GSTransferPath numbering) are replayed as given, 0 (the old PATH1) is read from a 16 KiB VU memory
  image, others are skipped.
- Gif_Path::ExecuteGSPacket (pcsx2/Gif_Unit.h): a GS packet ends at the tag with EOP set; a console's
  GIF likewise. Tag: NLOOP bits 0-14, EOP 15, PRE 46, PRIM 47-57, FLG 58-59, NREG 60-63 (0 = 16), REGS.
- GS register addresses (GS User's Manual register map; PCSX2 GSRegs.h enum GIF_A_D_REG).
- GSState::GetVideoMode (pcsx2/GS/GSState.cpp): SMODE1.CMOD (bits 13-14) 2 NTSC, 3 PAL; 0 is VESA
  unless SMODE1.LC (bits 3-9) is 22 or 32.
"""
import lzma
import os
import shutil
import struct
import subprocess
import sys

MIB = 1 << 20
PATH_BUFFER = 9 * MIB
STATE_VERSION_MAX = 9
STATE_SIZE = {8: 4 + 15 * 8 + 2 * 12 * 8 + (8 + 8 + 4 + 4 + 8) + 8 + 2 * 4 + 4 * MIB + 4 * (16 + 4) + 4}
STATE_SIZE[9] = STATE_SIZE[8] + 4 + 4 + 8 + 8 + 8 + 16 + 4 + 4 + 4 + 1
REGISTERS = {0x00, 0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08, 0x09, 0x0A, 0x0C, 0x0D, 0x14, 0x15, 0x16,
             0x17, 0x18, 0x19, 0x1A, 0x1B, 0x1C, 0x22, 0x34, 0x35, 0x36, 0x37, 0x3B, 0x3D, 0x3F,
             0x40, 0x41, 0x42, 0x43, 0x44, 0x45, 0x46, 0x47, 0x48, 0x49, 0x4A, 0x4B, 0x4C, 0x4D, 0x4E, 0x4F,
             0x50, 0x51, 0x52, 0x53, 0x54, 0x60, 0x61, 0x62}
CMOD = {'ntsc': 2, 'pal': 3, 'vesa': 0}


class Fail(Exception):
    pass


def raw_bytes(path):
    data = open(path, 'rb').read()
    if data.startswith(b'\xfd7zXZ\x00'):
        return lzma.decompress(data)
    if data.startswith(b'\x28\xb5\x2f\xfd'):
        if shutil.which('zstd') is None:
            raise Fail('zstd file and no zstd command to decompress it')
        return subprocess.run(['zstd', '-dc', path], check=True, capture_output=True).stdout
    return data


def u32(b, at):
    if at + 4 > len(b):
        raise Fail('byte %d: u32 past the end' % at)
    return struct.unpack_from('<I', b, at)[0]


def walk_gif(data, at, path, max_packet):
    """Walks one transfer's GIF tags; returns (tags, A+D writes)."""
    if len(data) % 16:
        raise Fail('byte %d: transfer of %d bytes is not whole qwords' % (at, len(data)))
    if len(data) > PATH_BUFFER:
        raise Fail('byte %d: transfer of %d bytes exceeds PCSX2\'s 9 MiB GIF path buffer (%d)' % (at, len(data), PATH_BUFFER))
    if max_packet and len(data) > max_packet:
        raise Fail('byte %d: transfer of %d bytes exceeds the packet bound %d' % (at, len(data), max_packet))
    q, n, tags, writes, eop = 0, len(data) // 16, 0, 0, False
    while q < n:
        lo, hi = struct.unpack_from('<QQ', data, 16 * q)
        nloop, eop = lo & 0x7FFF, bool(lo >> 15 & 1)
        flg, nreg = lo >> 58 & 3, (lo >> 60) or 16
        regs = [hi >> (4 * i) & 15 for i in range(nreg)]
        if flg == 3:
            raise Fail('byte %d: tag FLG 3' % (at + 16 * q))
        need = nloop * nreg if flg == 0 else (nloop * nreg + 1) // 2 if flg == 1 else nloop
        if q + 1 + need > n:
            raise Fail('byte %d: tag NLOOP %d needs %d qwords, the transfer has %d after it (a tag crosses the '
                       'transfer\'s end)' % (at + 16 * q, nloop, need, n - q - 1))
        if flg != 2 and 0x0B in regs:
            raise Fail('byte %d: register descriptor 0xB (unused)' % (at + 16 * q))
        if flg == 0:
            for k in range(need):
                if regs[k % nreg] == 0xE:
                    address = data[16 * (q + 1 + k) + 8]
                    writes += 1
                    if address not in REGISTERS:
                        raise Fail('byte %d: A+D write to unused register address 0x%02X' % (at + 16 * (q + 1 + k), address))
        tags += 1
        q += 1 + need
    if not eop:
        raise Fail('byte %d: path %d transfer\'s last tag has EOP = 0 (a GS packet ends at EOP)' % (at, path))
    return tags, writes


def check(path, video=None, max_packet=0):
    b = raw_bytes(path)
    at = 0
    first = u32(b, 0)
    if first == 0xFFFFFFFF:
        header_size = u32(b, 4)
        if header_size < 36:
            raise Fail('header size %d < 36' % header_size)
        h = b[8:8 + header_size]
        version, state_size, serial_off, serial_size, _crc, sw, sh, shot_off, shot_size = struct.unpack_from('<9I', h, 0)
        if serial_off + serial_size > header_size:
            raise Fail('serial outside the header')
        if shot_size != sw * sh * 4 or shot_off + shot_size > header_size:
            raise Fail('screenshot %dx%d with %d bytes' % (sw, sh, shot_size))
        at = 8 + header_size
    else:
        state_size = u32(b, 4)
        at = 8
        version = None
    state = b[at:at + state_size]
    if len(state) != state_size or state_size < 4:
        raise Fail('state of %d bytes cut or too small' % state_size)
    blob_version = u32(state, 0)
    if version is not None and version != blob_version:
        raise Fail('header state_version %d, blob %d' % (version, blob_version))
    if blob_version > STATE_VERSION_MAX:
        raise Fail('state version %d > PCSX2\'s STATE_VERSION %d' % (blob_version, STATE_VERSION_MAX))
    if blob_version in STATE_SIZE and state_size != STATE_SIZE[blob_version]:
        raise Fail('version %d state of %d bytes, not GSState::Freeze\'s %d: PCSX2 would read its fields at other '
                   'offsets' % (blob_version, state_size, STATE_SIZE[blob_version]))
    at += state_size
    regs = b[at:at + 8192]
    if len(regs) != 8192:
        raise Fail('privileged registers cut')
    at += 8192
    transfers = largest = tags = writes = 0
    last_type = None
    while at < len(b):
        t = b[at]
        if t == 0:
            if at + 6 > len(b):
                raise Fail('byte %d: transfer header cut' % at)
            p, size = b[at + 1], u32(b, at + 2)
            if p not in (1, 2, 3):
                raise Fail('byte %d: transfer path %d (new dumps use 1 PATH2, 2 PATH3, 3 PATH1)' % (at, p))
            data = b[at + 6:at + 6 + size]
            if len(data) != size:
                raise Fail('byte %d: transfer of %d bytes cut' % (at, size))
            tg, wr = walk_gif(data, at + 6, p, max_packet)
            transfers, largest, tags, writes = transfers + 1, max(largest, size), tags + tg, writes + wr
            at += 6 + size
        elif t == 1:
            at += 2
        elif t == 2:
            at += 5
        elif t == 3:
            at += 1 + 8192
        else:
            raise Fail('byte %d: packet type %d' % (at, t))
        if at > len(b):
            raise Fail('last packet cut')
        last_type = t
    if last_type != 1:
        raise Fail('the dump does not end with a vsync')
    smode1 = struct.unpack_from('<Q', regs, 0x10)[0]
    cmod, lc = smode1 >> 13 & 3, smode1 >> 3 & 0x7F
    if video is not None and (cmod != CMOD[video] or (video == 'vesa' and lc in (22, 32))):
        raise Fail('SMODE1 0x%x: CMOD %d LC %d is not %s for PCSX2' % (smode1, cmod, lc, video))
    return 'OK %s: state v%d, %d transfers (largest %d bytes), %d GIF tags, %d A+D writes, SMODE1 CMOD %d' % (
        os.path.basename(path), blob_version, transfers, largest, tags, writes, cmod)


def main(argv):
    video, max_packet, files, failed = None, 0, [], False
    i = 0
    while i < len(argv):
        if argv[i] == '--video':
            video, i = argv[i + 1], i + 2
        elif argv[i] == '--max-packet':
            max_packet, i = int(argv[i + 1]), i + 2
        else:
            files.append(argv[i])
            i += 1
    for f in files:
        try:
            print(check(f, video, max_packet))
        except Fail as e:
            print('FAIL %s: %s' % (f, e))
            failed = True
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
