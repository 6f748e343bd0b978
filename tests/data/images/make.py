#!/usr/bin/env python3
"""Writes the tiny test images of tests/unit/test_image.c (committed; run
again only to change them). PNGs are written by hand so that palettes and
bit depths are exactly known; the other formats are converted with oiiotool."""
import struct, subprocess, zlib, os

def chunk(kind, data):
    c = struct.pack('>I', len(data)) + kind + data
    return c + struct.pack('>I', zlib.crc32(kind + data) & 0xffffffff)

def png(path, w, h, depth, ctype, rows, plte=None, trns=None, gama=None):
    raw = b''
    for r in rows:
        raw += b'\0' + bytes(r)
    out = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, depth, ctype, 0, 0, 0))
    if gama:
        out += chunk(b'gAMA', struct.pack('>I', gama))
    if plte:
        out += chunk(b'PLTE', bytes(sum(plte, [])))
    if trns:
        out += chunk(b'tRNS', bytes(trns))
    out += chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b'')
    open(path, 'wb').write(out)

def rgb_px(c, r):
    return [c * 60 + 10, r * 100 + 20, 200 - c * 40]

# rgb.png: 4 x 2, 8-bit RGB, every pixel different.
png('rgb.png', 4, 2, 8, 2, [sum((rgb_px(c, r) for c in range(4)), []) for r in range(2)])
# rgb16.png: 2 x 1, 16-bit RGB.
png('rgb16.png', 2, 1, 16, 2, [[0x12, 0x34, 0x80, 0x00, 0xff, 0xff, 0x00, 0x00, 0x40, 0x00, 0xc0, 0x00]])
# grey.png: 3 x 1 greyscale; greya.png: 2 x 1 grey + alpha; rgba.png: 2 x 1 RGBA.
png('grey.png', 3, 1, 8, 0, [[0, 128, 255]])
png('greya.png', 2, 1, 8, 4, [[200, 255, 100, 64]])
png('rgba.png', 2, 1, 8, 6, [[255, 0, 0, 255, 0, 200, 100, 51]])
# pal.png: 4 x 2 paletted, 6 entries; entry 4 repeats entry 1's colour
# (a palette may do that); entries 0 and 2 have tRNS alpha.
plte = [[255, 0, 0], [0, 255, 0], [0, 0, 255], [255, 255, 0], [0, 255, 0], [40, 80, 120]]
png('pal.png', 4, 2, 8, 3, [[0, 1, 2, 3], [4, 5, 0, 1]], plte=plte, trns=[128, 255, 0])
# gamma.png: 1 x 1 RGB with a gAMA chunk of 1/1.0 (linear data).
png('gamma1.png', 2, 1, 8, 2, [[128, 128, 128, 64, 64, 64]], gama=100000)

def gif(path, w, h, pal, idx, transparent=None):
    """A GIF with a 256-entry global table; 9-bit LZW codes with a clear
    code every 254 codes, so the code table never grows."""
    ct = b''.join(bytes(c) for c in pal) + b'\0' * 3 * (256 - len(pal))
    out = b'GIF89a' + struct.pack('<HHBBB', w, h, 0xF7, 0, 0) + ct
    if transparent is not None:
        out += b'\x21\xf9\x04' + bytes([1, 0, 0, transparent, 0])
    out += b'\x2c' + struct.pack('<HHHHB', 0, 0, w, h, 0)
    codes = []
    for i, v in enumerate(idx):
        if i % 254 == 0:
            codes.append(256)
        codes.append(v)
    codes.append(257)
    bits = nb = 0
    data = bytearray()
    for c in codes:
        bits |= c << nb
        nb += 9
        while nb >= 8:
            data.append(bits & 255)
            bits >>= 8
            nb -= 8
    if nb:
        data.append(bits & 255)
    out += b'\x08'
    for i in range(0, len(data), 255):
        blk = data[i:i + 255]
        out += bytes([len(blk)]) + bytes(blk)
    out += b'\x00\x3b'
    open(path, 'wb').write(out)

# pal.gif: pal.png's indices and palette; index 2 transparent.
gif('pal.gif', 4, 2, plte, [0, 1, 2, 3, 4, 5, 0, 1], transparent=2)

def oiio(src, dst, *args):
    subprocess.run(['oiiotool', src, *args, '-o', dst], check=True)

oiio('rgb.png', 'rgb.tga')
oiio('rgb.png', 'rgb.ppm')
oiio('grey.png', 'grey.pgm')
oiio('rgb.png', 'rgb.tif')
oiio('rgb.png', 'rgb.jpg', '--attrib', 'Compression', 'jpeg:100')
# Float images: 2 x 1, values above 1.
subprocess.run(['oiiotool', '--create', '2x1', '3', '--fill:color=0.25,1.5,4', '0,0,1,1',
                '--fill:color=0.5,0.125,2', '1,0,2,1', '-d', 'half', '-o', 'float.exr'], check=True)
subprocess.run(['oiiotool', 'float.exr', '-d', 'float', '-o', 'float.hdr'], check=True)
