#!/usr/bin/env python3
"""Writes scenes/images/glass-panel-smiley.png: the glass panel's picture for
scenes/glass-panel.json (Ganovelli et al. exercise 8.6.2-2), 128x128 RGBA, a
smiley opaque (alpha 255) on a clear panel (alpha 0): its shadow is the
picture. Run from the repository root; the PNG is committed."""
import struct
import zlib

W = H = 128


def inside(x, y):
    cx, cy = (x + 0.5) / W * 2 - 1, (y + 0.5) / H * 2 - 1  # -1..1, y down
    r = (cx * cx + cy * cy) ** 0.5
    if 0.78 <= r <= 0.92:                                   # the face's rim
        return True
    for ex in (-0.33, 0.33):                                # the eyes
        if ((cx - ex) ** 2 + (cy + 0.28) ** 2) ** 0.5 <= 0.13:
            return True
    if 0.42 <= r <= 0.56 and cy > 0.12:                     # the smile
        return True
    return False


rows = b""
for y in range(H):
    row = b"\0"
    for x in range(W):
        row += bytes((240, 200, 60, 255)) if inside(x, y) else bytes((200, 220, 235, 0))
    rows += row


def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 8, 6, 0, 0, 0)) \
    + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")
with open("scenes/images/glass-panel-smiley.png", "wb") as f:
    f.write(png)
