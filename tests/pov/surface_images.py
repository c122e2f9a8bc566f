#!/usr/bin/env python3
# surface_images.py: writes the small PNG textures of the surface_* reference scenes
# (tests/pov/local.mk), so that they can be made again: 8-bit RGB, a different colour in
# every texel so that a lookup off by one texel shows.
#   surface_tex.png      16 x 8, no colour chunk (POV-Ray and scn take it as sRGB)
#   surface_linear.png   16 x 8, gAMA 1.0 (linear)
#   surface_g22.png      16 x 8, gAMA 0.45455 alone (a 2.2 power law, not sRGB's curve)
#   surface_mtl.png       4 x 4, no colour chunk: octa_uv.mtl's map_Kd
import os
import sys

# the PNG writer of the render tests' images (tests/render/mkimages.py)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'render'))
from mkimages import png  # noqa: E402


def write(name, w, h, texel, gamma=None):
    png(name, [[texel(x, y) for x in range(w)] for y in range(h)], gamma)


def rainbow(x, y):
    return (40 + 13 * x, 30 + 27 * y, 230 - 90 * ((x + y) % 2) - 5 * x)


write('surface_tex.png', 16, 8, rainbow)
write('surface_linear.png', 16, 8, rainbow, 100000)
write('surface_g22.png', 16, 8, rainbow, 45455)
write('surface_mtl.png', 4, 4, lambda x, y: (60 + 60 * x, 220 - 50 * y, 90 + 100 * ((x + y) % 2)))
