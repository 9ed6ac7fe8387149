#!/usr/bin/env python3
"""The largest difference of two 8-bit PNG pictures, over all channels, in 1/255 steps.

Usage: png_diff.py [--sum] A.png B.png [X0 X1]   (columns [X0, X1) only)
With --sum, prints the sum of the absolute differences over all channels instead.
png_diff.py --peak A.png prints A's largest channel value (0: a black picture);
png_diff.py --mean A.png its mean channel value (0 to 255).
A grey picture counts as three equal channels, so a grey `render --display` compares
with the viewer's RGB screenshot. Prints the maximum; exits 2 when the sizes differ.
Standard library only (zlib); handles the non-interlaced 8-bit grey, RGB and RGBA that
sunglint writes.
"""
import struct
import sys
import zlib


def read_png(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path}: not a PNG")
    pos, idat, w = 8, b"", None
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if kind == b"IHDR":
            w, h, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or interlace != 0 or ctype not in (0, 2, 6):
                sys.exit(f"{path}: unsupported PNG (depth {depth}, type {ctype})")
            ch = {0: 1, 2: 3, 6: 4}[ctype]
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            break
    raw = zlib.decompress(idat)
    stride = w * ch
    rows, prev = [], bytearray(stride)
    for y in range(h):
        ftype = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - ch] if i >= ch else 0
            b = prev[i]
            c = prev[i - ch] if i >= ch else 0
            if ftype == 1:
                line[i] = (line[i] + a) & 255
            elif ftype == 2:
                line[i] = (line[i] + b) & 255
            elif ftype == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif ftype == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + pred) & 255
        rows.append(line)
        prev = line
    # As RGB rows.
    out = []
    for line in rows:
        if ch == 1:
            out.append([v for v in line for _ in range(3)])
        else:
            out.append([line[x * ch + c] for x in range(w) for c in range(3)])
    return w, h, out


def main():
    args = sys.argv[1:]
    if args[:1] == ["--peak"]:
        print(max(max(row) for row in read_png(args[1])[2]))
        return
    if args[:1] == ["--mean"]:
        rows = read_png(args[1])[2]
        print(round(sum(sum(row) for row in rows) / sum(len(row) for row in rows), 2))
        return
    total = args[:1] == ["--sum"]
    if total:
        args = args[1:]
    wa, ha, a = read_png(args[0])
    wb, hb, b = read_png(args[1])
    if (wa, ha) != (wb, hb):
        print(f"sizes differ: {wa}x{ha} and {wb}x{hb}")
        sys.exit(2)
    x0, x1 = (int(args[2]), int(args[3])) if len(args) > 3 else (0, wa)
    worst = summed = 0
    for ra, rb in zip(a, b):
        for i in range(3 * x0, 3 * x1):
            d = abs(ra[i] - rb[i])
            worst = max(worst, d)
            summed += d
    print(summed if total else worst)


main()
