#!/usr/bin/env python3
"""mkimages.py: writes the tiny skybox maps of the render tests, byte by byte, with the
standard library only (the files are in the repository; this script documents them and
can rebuild them: run it in tests/render/).

  sky_4x2.png      8-bit RGB, 4 x 2 texels, gAMA chunk 1.0 (100000): linear, texel = v / 255
  sky_srgb.png     8-bit RGB, 1 x 1 texel (64, 128, 255), no gAMA/sRGB chunk: sRGB-decoded
  sky_2x1.exr      32-bit float RGB OpenEXR, 2 x 1 texels, no compression: linear, HDR values

The texel values are listed in the .expect files that use them."""
import struct
import zlib

# sky_4x2.png: rows top first; values in 1/255 units (multiples of 51 = 0.2)
SKY_4X2 = [
    [(255, 51, 0), (204, 102, 51), (153, 153, 102), (102, 204, 153)],   # row 0 (top: d.y > 0)
    [(0, 153, 255), (51, 255, 204), (102, 0, 153), (153, 51, 102)],     # row 1 (bottom)
]
SKY_SRGB = [[(64, 128, 255)]]
SKY_2X1 = [[(0.25, 0.5, 2.0), (4.0, 0.125, 0.0)]]


def png(path, rows, gamma):
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    h, w = len(rows), len(rows[0])
    raw = b"".join(b"\0" + bytes(c for px in row for c in px) for row in rows)
    out = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    if gamma is not None:
        out += chunk(b"gAMA", struct.pack(">I", gamma))
    out += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(out)


def exr(path, rows):
    h, w = len(rows), len(rows[0])

    def attr(name, kind, data):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(data)) + data

    chlist = b"".join(c.encode() + b"\0" + struct.pack("<iB3xii", 2, 0, 1, 1) for c in "BGR") + b"\0"
    header = (attr("channels", "chlist", chlist)
              + attr("compression", "compression", b"\0")
              + attr("dataWindow", "box2i", struct.pack("<iiii", 0, 0, w - 1, h - 1))
              + attr("displayWindow", "box2i", struct.pack("<iiii", 0, 0, w - 1, h - 1))
              + attr("lineOrder", "lineOrder", b"\0")
              + attr("pixelAspectRatio", "float", struct.pack("<f", 1.0))
              + attr("screenWindowCenter", "v2f", struct.pack("<ff", 0.0, 0.0))
              + attr("screenWindowWidth", "float", struct.pack("<f", 1.0))
              + b"\0")
    start = 8 + len(header) + 8 * h
    blocks, offsets = b"", []
    for y, row in enumerate(rows):
        data = b"".join(struct.pack("<%df" % w, *(px[k] for px in row)) for k in (2, 1, 0))  # B, G, R
        offsets.append(start + len(blocks))
        blocks += struct.pack("<ii", y, len(data)) + data
    with open(path, "wb") as f:
        f.write(struct.pack("<iI", 20000630, 2) + header + struct.pack("<%dQ" % h, *offsets) + blocks)


if __name__ == "__main__":
    png("sky_4x2.png", SKY_4X2, 100000)
    png("sky_srgb.png", SKY_SRGB, None)
    exr("sky_2x1.exr", SKY_2X1)
