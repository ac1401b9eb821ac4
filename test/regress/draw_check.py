#!/usr/bin/python3
# test/regress/draw_check.py — checks a PNG that whirl drew itself against
# the table it shows, independently of whirl's code: the PNG is decoded
# here (chunk CRCs, zlib's Adler-32, the palette), the frame is found in the
# pixels (the longest dark rows and columns), and points of the table,
# mapped through the script's ranges onto that frame, must have the
# series' colour within a few pixels.
#   draw_check.py info PNG                      -> "W H colourtype"
#   draw_check.py points PNG XLO XHI YLO YHI LOGY RGB TOL FILE
#       FILE: lines "x y" of data points; prints "found N of M"
#   draw_check.py dark PNG X0 Y0 X1 Y1          -> dark pixels in the box
#   draw_check.py frame PNG                     -> "L R T B"
# SPDX-License-Identifier: BSD-3-Clause
import math
import struct
import sys
import zlib


def decode(path):
    data = open(path, 'rb').read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise SystemExit('not a PNG: %s' % path)
    i, idat, pal, ihdr = 8, b'', None, None
    while i < len(data):
        n, = struct.unpack('>I', data[i:i + 4])
        kind, body = data[i + 4:i + 8], data[i + 8:i + 8 + n]
        crc, = struct.unpack('>I', data[i + 8 + n:i + 12 + n])
        if zlib.crc32(kind + body) & 0xffffffff != crc:
            raise SystemExit('bad CRC in chunk %r' % kind)
        if kind == b'IHDR':
            ihdr = struct.unpack('>IIBBBBB', body)
        elif kind == b'PLTE':
            pal = [tuple(body[k:k + 3]) for k in range(0, n, 3)]
        elif kind == b'IDAT':
            idat += body
        elif kind == b'IEND':
            if i + 12 + n != len(data):
                raise SystemExit('bytes after IEND')
            break
        i += 12 + n
    w, h, depth, ctype, _, _, interlace = ihdr
    if depth != 8 or interlace != 0:
        raise SystemExit('unexpected depth %d or interlace %d' % (depth, interlace))
    raw = zlib.decompress(idat)  # checks the Adler-32 trailer
    bpp = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[ctype]
    stride = w * bpp
    if len(raw) != h * (stride + 1):
        raise SystemExit('%d bytes of image data, %d expected' % (len(raw), h * (stride + 1)))
    rows, prev = [], bytearray(stride)
    for y in range(h):
        f = raw[y * (stride + 1)]
        row = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        if f != 0:  # undo filters 1-4 (gnuplot's pictures use them)
            for x in range(stride):
                a = row[x - bpp] if x >= bpp else 0
                b = prev[x]
                c = prev[x - bpp] if x >= bpp else 0
                if f == 1:
                    p = a
                elif f == 2:
                    p = b
                elif f == 3:
                    p = (a + b) // 2
                else:
                    pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                    p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                row[x] = (row[x] + p) & 255
        prev = row
        if ctype == 3:
            rows.append([pal[v] for v in row])
        elif ctype in (2, 6):
            rows.append([tuple(row[k:k + 3]) for k in range(0, stride, bpp)])
        else:
            rows.append([(v, v, v) for v in row[::bpp]])
    return w, h, ctype, rows


def dark(c):
    return sum(c) < 200


def frame(w, h, im):
    cols = [x for x in range(w) if sum(1 for y in range(h) if dark(im[y][x])) > h // 2]
    rows = [y for y in range(h) if sum(1 for x in range(w) if dark(im[y][x])) > w // 2]
    return cols[0], cols[-1], rows[0], rows[-1]


def inked(c, rgb):
    """Is C the ink RGB over white at a coverage of at least a half?"""
    k = max(range(3), key=lambda i: 255 - rgb[i])
    if rgb[k] == 255:
        return c == (255, 255, 255)
    a = (255 - c[k]) / (255 - rgb[k])
    return a >= 0.5 and all(abs(c[i] - (a * rgb[i] + (1 - a) * 255)) < 25 for i in range(3))


def near(im, x, y, rgb, tol, w, h):
    for j in range(max(0, y - tol), min(h, y + tol + 1)):
        for i in range(max(0, x - tol), min(w, x + tol + 1)):
            if inked(im[j][i], rgb):
                return True
    return False


def main():
    what, path = sys.argv[1], sys.argv[2]
    w, h, ctype, im = decode(path)
    if what == 'info':
        print(w, h, ctype)
    elif what == 'frame':
        print(*frame(w, h, im))
    elif what == 'dark':
        x0, y0, x1, y1 = map(int, sys.argv[3:7])
        print(sum(1 for y in range(y0, y1) for x in range(x0, x1) if dark(im[y][x])))
    elif what == 'points':
        xlo, xhi, ylo, yhi = map(float, sys.argv[3:7])
        logy = sys.argv[7] == '1'
        rgb = tuple(int(sys.argv[8][k:k + 2], 16) for k in (1, 3, 5))
        tol = int(sys.argv[9])
        L, R, T, B = frame(w, h, im)
        if logy:
            ylo, yhi = math.log10(ylo), math.log10(yhi)
        found = total = 0
        for line in open(sys.argv[10]):
            x, y = map(float, line.split()[:2])
            if logy:
                y = math.log10(y)
            if not (xlo <= x <= xhi and ylo <= y <= yhi):
                continue
            px = L + (x - xlo) / (xhi - xlo) * (R - L)
            py = B - (y - ylo) / (yhi - ylo) * (B - T)
            total += 1
            found += near(im, int(round(px)), int(round(py)), rgb, tol, w, h)
        print('found %d of %d' % (found, total))


main()
