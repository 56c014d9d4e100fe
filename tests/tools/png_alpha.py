#!/usr/bin/env python3
"""Prints the alpha of a PNG's top-left pixel and the fraction of opaque pixels: "corner=0 opaque=0.62".
Standard library only (zlib), 8-bit RGBA non-interlaced PNGs (what Cairo writes).  usage: png_alpha.py FILE"""
import struct
import sys
import zlib


def main():
    data = open(sys.argv[1], "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    at, idat, width, height, ctype = 8, b"", 0, 0, 0
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            width, height, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and interlace == 0, "only 8-bit non-interlaced"
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    if ctype != 6:
        print(f"colour-type={ctype} (no alpha)")
        return
    raw = zlib.decompress(idat)
    bpp, stride = 4, width * 4
    prev = bytearray(stride)
    opaque, corner = 0, None
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        opaque += sum(1 for i in range(3, stride, 4) if line[i] == 255)
        if corner is None:
            corner = line[3]
        prev = line
    print(f"corner={corner} opaque={opaque / (width * height):.2f}")


if __name__ == "__main__":
    main()
