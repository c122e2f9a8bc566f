"""scenes.py: writes the benchmark scenes of bench/run into a build folder: small scn
files whose loops make the objects, so that nothing big is committed."""

import os
import sys
import struct

# the headline's camera, lights, sky and settings, which the textured scene shares
HEADLINE_SETUP = """camera {{ location <0, 7, -16>  look_at <0, 0.5, 0>  fov 60  resolution 1280, 1024 }}
light  {{ position <-10, 14, -8> }}
light  {{ position <12, 10, -4>  intensity 0.6 }}
skybox {{ zenith <0.15, 0.3, 0.7>  horizon <0.75, 0.82, 0.9> }}
samples {{ count 5  pattern jittered }}
max_depth 8
"""

HEADLINE = """// {what}
{setup}material floor  {{ diffuse checker(<0.9, 0.9, 0.9>, <0.25, 0.25, 0.3>, 1)  reflect 0.1 }}
material mirror {{ diffuse 0.05  specular 0.8  shininess 200  reflect 0.85 }}
material glass  {{ diffuse 0  specular 0.6  shininess 300  reflect 0.08  transmit 0.9  ior 1.5 }}
material red    {{ diffuse <0.8, 0.2, 0.15>  specular 0.3  shininess 40 }}
material green  {{ diffuse <0.2, 0.7, 0.25>  specular 0.3  shininess 40 }}
material blue   {{ diffuse <0.2, 0.3, 0.8>  specular 0.3  shininess 40 }}
material sand   {{ diffuse <0.8, 0.7, 0.45> }}
plane {{ <0, 1, 0>, 0  material floor }}
{loops}"""

# n spheres at random in a box of side 2 s around <0, s, 0> above a floor, the radius
# giving a fixed share of the box's volume: the picture looks alike for any n
FIELD = """// {n} spheres at random in a box, each {share:g} of the box's volume in all
camera {{ location <0, {cy:g}, {cz:g}>  look_at <0, {s:g}, 0>  fov 55  resolution {w}, {h} }}
light  {{ position <{lx:g}, {ly:g}, {lz:g}> }}
skybox {{ zenith <0.15, 0.3, 0.7>  horizon <0.75, 0.82, 0.9> }}
material red   {{ diffuse <0.8, 0.2, 0.15>  specular 0.3  shininess 40 }}
material green {{ diffuse <0.2, 0.7, 0.25>  specular 0.3  shininess 40 }}
material blue  {{ diffuse <0.2, 0.3, 0.8>  specular 0.3  shininess 40 }}
material sand  {{ diffuse <0.8, 0.7, 0.45> }}
{loops}"""


def sphere_loops(n, materials, centre, radius, seed=0):
    """for-loops placing n spheres with rand(), split evenly over the materials; centre
    is a format string of the index expression k, radius an scn expression."""
    out, first = [], 0
    for m, name in enumerate(materials):
        count = n // len(materials) + (1 if m < n % len(materials) else 0)
        if count == 0:
            continue
        k = f"(i + {first + seed})"
        out.append(f"for i in 0 .. {count} {{ sphere {{ {centre.format(k=k)}, {radius.format(k=k)}"
                   f"  material {name} }} }}\n")
        first += count
    return "".join(out)


# the headline's spheres: where, and how big
HEADLINE_CENTRE = "<20 * rand(3 * {k}) - 10, 0.3 + 3.5 * rand(3 * {k} + 1), 20 * rand(3 * {k} + 2) - 8>"
HEADLINE_RADIUS = "0.25 + 0.35 * rand(7 * {k} + 5)"


def headline(path, what="headline: 1000 spheres over a checkered floor, a tenth mirror and a tenth glass",
             setup=HEADLINE_SETUP.format()):
    mats = ["mirror"] + ["glass"] + ["red", "green", "blue", "sand"] * 2
    write(path, HEADLINE.format(what=what, setup=setup,
                                loops=sphere_loops(1000, mats, HEADLINE_CENTRE, HEADLINE_RADIUS)))


def corner(path):
    """The headline's floor and lights, its cost in one corner: 400 mirror and glass spheres
    packed at the back left, the top left of the picture (the MPI bench's imbalance)."""
    centre = "<-9 + 4 * rand(3 * {k}), 2 + 3 * rand(3 * {k} + 1), 6 + 4 * rand(3 * {k} + 2)>"
    write(path, HEADLINE.format(what="corner: the headline's floor, 400 mirror and glass spheres in its top left corner",
                                setup=HEADLINE_SETUP.format(),
                                loops=sphere_loops(400, ["mirror", "glass"], centre, "0.3 + 0.2 * rand(7 * {k} + 5)")))


# The scenes of LANGUAGE.md section 12's lights and cameras for the table: the headline's
# spheres and floor at 640x480 under another camera, lights or fog ({camera} and {lights}
# are whole statements).
SECTION12_SETUP = """{camera}
{lights}
skybox {{ zenith <0.15, 0.3, 0.7>  horizon <0.75, 0.82, 0.9> }}
samples {{ count 5  pattern jittered }}
max_depth 8
{extra}"""
HEADLINE_CAMERA = "location <0, 7, -16>  look_at <0, 0.5, 0>  fov 60  resolution 640, 480"
HEADLINE_LIGHTS = "light  { position <-10, 14, -8> }\nlight  { position <12, 10, -4>  intensity 0.6 }"


def headline_variant(path, what, camera=HEADLINE_CAMERA, lights=HEADLINE_LIGHTS, extra=""):
    """The headline at 640x480 with camera (the camera block's contents), lights or extra
    statements of its own."""
    headline(path, what, SECTION12_SETUP.format(camera="camera { %s }" % camera, lights=lights, extra=extra))


def spotlights(path):
    """The headline's spheres under four spotlights with fade, no other light."""
    lights = "\n".join(
        "light  { position <%g, 12, %g>  spotlight { point_at <%g, 0, %g>  radius 14  falloff 24  tightness 4 }"
        "  fade_distance 14  fade_power 2 }" % (x, z, x / 2, z / 2 + 2) for x, z in ((-9, -8), (9, -8), (-7, 8), (7, 8)))
    headline_variant(path, "spotlights: the headline's spheres under four spotlights with fade", lights=lights)


def fog(path):
    headline_variant(path, "fog: the headline with fog", extra="fog { distance 18  color <0.7, 0.75, 0.8> }\n")


def orthographic(path):
    headline_variant(path, "orthographic: the headline's spheres seen from above, orthographic",
                     camera="orthographic  width 26  location <0, 20, -12>  look_at <0, 0, 1>  resolution 640, 480")


def focal_blur(path):
    headline_variant(path, "focal blur: the headline through a lens, sharp at the middle",
                     camera=HEADLINE_CAMERA + "  aperture 0.6  focal_point <0, 0.5, 1>")


# Spheres and boxes on a floor under one jittered 8 x 8 area light ({n} of each; the table's
# at 640x480, 5 samples a pixel; scn converge's few at 320x240, its own samples).
SOFT = """// soft shadows: {n} spheres and {n} boxes on a floor under one area light, 8 x 8, jittered
camera {{ location <0, 6, -{cz}>  look_at <0, 0.5, 0>  fov 55  resolution {w}, {h} }}
light  {{ position <-5, 10, -6>  area {{ <3, 0, 0>, <0, 0, 3>, 8, 8  jitter }} }}
skybox {{ zenith <0.15, 0.3, 0.7>  horizon <0.75, 0.82, 0.9> }}
{samples}material floor {{ diffuse <0.8, 0.78, 0.72> }}
material red   {{ diffuse <0.8, 0.2, 0.15>  specular 0.3  shininess 40 }}
material green {{ diffuse <0.2, 0.7, 0.25>  specular 0.3  shininess 40 }}
material blue  {{ diffuse <0.2, 0.3, 0.8>  specular 0.3  shininess 40 }}
plane {{ <0, 1, 0>, 0  material floor }}
{loops}for i in 0 .. {n} {{ box {{ <{s} * rand(5 * i + 9000) - {h2}, 0, {s} * rand(5 * i + 9001) - {h2}>,
  <{s} * rand(5 * i + 9000) - {h2} + {b}, {b} * (0.5 + 1.5 * rand(5 * i + 9002)), {s} * rand(5 * i + 9001) - {h2} + {b}>
  material blue }} }}
"""


def soft_shadows(path, n=150, width=640, height=480, samples=5):
    """n spheres and n boxes in a square (side 16 for the table's hundreds, 6 for a few) on a
    floor, lit by one jittered 8 x 8 area light; samples 0: no samples statement."""
    side = 16 if n > 20 else 6
    r = 0.35 if n > 20 else 0.7
    centre = ("<%g * rand(3 * {k}) - %g, %g, %g * rand(3 * {k} + 2) - %g>" % (side, side / 2, r, side, side / 2))
    write(path, SOFT.format(n=n, cz=14 if n > 20 else 8, w=width, h=height, s=side, h2=side / 2, b=2 * r,
                            samples="samples { count %d  pattern jittered }\n" % samples if samples else "",
                            loops=sphere_loops(n, ["red", "green"], centre, repr(r))))


def field(path, n, width=640, height=480):
    s = 10.0
    share = 0.03
    # n spheres of radius r fill share of (2 s)^3
    r = (share * (2 * s) ** 3 * 3 / (4 * 3.141592653589793 * n)) ** (1 / 3)
    centre = f"<{2 * s} * rand(3 * {{k}}) - {s}, {2 * s} * rand(3 * {{k}} + 1), {2 * s} * rand(3 * {{k}} + 2) - {s}>"
    write(path, FIELD.format(n=n, share=share, cy=1.6 * s, cz=-3.2 * s, s=s, w=width, h=height,
                             lx=-2 * s, ly=4 * s, lz=-3 * s,
                             loops=sphere_loops(n, ["red", "green", "blue", "sand"], centre, repr(r))))


# Spheres with a material of their own each, a third mirror, a third glass and a third
# diffuse, their colours, reflection and index from rand() (LANGUAGE.md section 5's
# inline material): the mix of mirrors and glass at which scn's margin over POV-Ray is
# smallest (issue 24's first measurement)
OWN_MATERIALS = (
    "diffuse <0.05 + 0.1 * rand({k}), 0.05 + 0.1 * rand({k} + 1), 0.05 + 0.1 * rand({k} + 2)>  specular 0.8"
    "  shininess 200  reflect 0.7 + 0.25 * rand({k} + 3)",
    "diffuse 0  specular 0.6  shininess 300  reflect 0.05 + 0.1 * rand({k} + 3)  transmit 0.8 + 0.15 * rand({k} + 4)"
    "  ior 1.3 + 0.4 * rand({k} + 5)",
    "diffuse <0.2 + 0.7 * rand({k}), 0.2 + 0.7 * rand({k} + 1), 0.2 + 0.7 * rand({k} + 2)>  specular 0.3"
    "  shininess 40")

OWN = """// {what}
{camera}
light  {{ position <-10, 14, -8> }}
light  {{ position <12, 10, -4>  intensity 0.6 }}
skybox {{ zenith <0.15, 0.3, 0.7>  horizon <0.75, 0.82, 0.9> }}
samples {{ count 5  pattern jittered }}
max_depth 8
material floor  {{ diffuse checker(<0.9, 0.9, 0.9>, <0.25, 0.25, 0.3>, 1)  reflect 0.1 }}
plane {{ <0, 1, 0>, 0  material floor }}
{loops}"""


def own_material_loops(n, centre, radius):
    out, first = [], 0
    for m, material in enumerate(OWN_MATERIALS):
        count = n // 3 + (1 if m < n % 3 else 0)
        k = f"(i + {first})"
        out.append(f"for i in 0 .. {count} {{ sphere {{ {centre.format(k=k)}, {radius.format(k=k)}"
                   f"  material {{ {material.format(k='11 * ' + k)} }} }} }}\n")
        first += count
    return "".join(out)


def mirrors(path):
    """The headline's 1000 spheres and floor at 1280x1024, each sphere with a material of
    its own, a third mirror and a third glass."""
    write(path, OWN.format(what="mirrors: the headline's 1000 spheres, each its own material, a third mirror, a third glass",
                           camera=HEADLINE_SETUP.splitlines()[0].replace("{{", "{").replace("}}", "}"),
                           loops=own_material_loops(1000, HEADLINE_CENTRE, HEADLINE_RADIUS)))


def dense_mirrors(path, n=100000):
    """n spheres of their own materials (as mirrors) in the field's box, 640x480, max_depth 8."""
    s, share = 10.0, 0.03
    r = (share * (2 * s) ** 3 * 3 / (4 * 3.141592653589793 * n)) ** (1 / 3)
    centre = f"<{2 * s} * rand(3 * {{k}}) - {s}, {2 * s} * rand(3 * {{k}} + 1), {2 * s} * rand(3 * {{k}} + 2) - {s}>"
    camera = (f"camera {{ location <0, {1.6 * s:g}, {-3.2 * s:g}>  look_at <0, {s:g}, 0>  fov 55  "
              f"resolution 640, 480 }}")
    write(path, OWN.format(what=f"dense mirrors: {n} spheres in a box, each its own material, a third mirror, a third glass",
                           camera=camera, loops=own_material_loops(n, centre, repr(r))))


QUADRICS = """// {n} quadrics and tori at random over a floor: boxes, cylinders, cones, ellipsoids
// (spheres under an uneven scale) and tori, a fifth of each, each turned at random
camera {{ location <0, 9, -24>  look_at <0, 1, 0>  fov 60  resolution {w}, {h} }}
light  {{ position <-15, 30, -20> }}
samples {{ count 5  pattern jittered }}
skybox {{ zenith <0.15, 0.3, 0.7>  horizon <0.75, 0.82, 0.9> }}
material floor {{ diffuse checker(<0.9, 0.9, 0.9>, <0.3, 0.3, 0.35>, 2) }}
material red   {{ diffuse <0.8, 0.2, 0.15>  specular 0.3  shininess 40 }}
material green {{ diffuse <0.2, 0.7, 0.25>  specular 0.3  shininess 40 }}
material blue  {{ diffuse <0.2, 0.3, 0.8>  specular 0.3  shininess 40 }}
material sand  {{ diffuse <0.8, 0.7, 0.45> }}
material grey  {{ diffuse 0.6  specular 0.2  shininess 20 }}
plane {{ <0, 1, 0>, 0  material floor }}
let k = {k}
// each in a box 40 x 8 x 40 above the floor, of half-size s about k, turned at random
{loops}"""

QUADRIC_SHAPES = [
    ("red", "box {{ <-s, -s, -s>, <s, s, s>"),
    ("green", "cylinder {{ <0, -s, 0>, <0, s, 0>, 0.6 * s"),
    ("blue", "cone {{ <0, -s, 0>, s, <0, s, 0>, 0"),
    ("sand", "sphere {{ <0, 0, 0>, s  scale <1, 0.4, 0.7>"),
    ("grey", "torus {{ s, 0.3 * s"),
]


def quadrics(path, n, width=640, height=480):
    """n mixed solids, n / 5 of each kind of QUADRIC_SHAPES, placed with rand(); the
    size keeps the share of the box they fill as the spheres field's."""
    box = 40 * 8 * 40
    s = (0.03 * box / n) ** (1 / 3) * 0.55
    loops = []
    for m, (material, head) in enumerate(QUADRIC_SHAPES):
        count = n // len(QUADRIC_SHAPES) + (1 if m < n % len(QUADRIC_SHAPES) else 0)
        k = f"(i + {m * (n // len(QUADRIC_SHAPES) + 1)})"
        loops.append(
            f"for i in 0 .. {count} {{\n"
            f"  let s = k * (0.6 + 0.8 * rand(5 * {k} + 3))\n"
            f"  {head.format()}  rotate <360 * rand(5 * {k} + 4), 360 * rand(7 * {k} + 1), 0>\n"
            f"    translate <40 * rand(5 * {k}) - 20, 0.5 + 8 * rand(5 * {k} + 1), 40 * rand(5 * {k} + 2) - 12>"
            f"  material {material} }}\n}}\n")
    write(path, QUADRICS.format(n=n, w=width, h=height, k=repr(s), loops="".join(loops)))


CSG_WALL = """// a wall of {n} bricks, each a box with a cylinder hole through it (a difference)
camera {{ location <-6, 5, -16>  look_at <4, 5.5, 0>  fov 60  resolution {w}, {h} }}
light  {{ position <-10, 20, -25> }}
samples {{ count 5  pattern jittered }}
skybox {{ zenith <0.15, 0.3, 0.7>  horizon <0.75, 0.82, 0.9> }}
material ground {{ diffuse checker(<0.9, 0.9, 0.9>, <0.3, 0.3, 0.35>, 1) }}
material brick {{ diffuse <0.7, 0.3, 0.2>  specular 0.1  shininess 20 }}
material bore  {{ diffuse <0.9, 0.85, 0.7> }}
plane {{ <0, 1, 0>, 0  material ground }}
for row in 0 .. {rows} {{
  for col in 0 .. {cols} {{
    let x = 0.5 * (row - 2 * floor(row / 2)) + col - {half}
    difference {{
      box {{ <x, row * 0.5, 0>, <x + 0.96, row * 0.5 + 0.46, 0.5>
            material {{ like brick  diffuse <0.7, 0.3, 0.2> * (0.8 + 0.4 * rand(row * {cols} + col)) }} }}
      cylinder {{ <x + 0.48, row * 0.5 + 0.23, -0.1>, <x + 0.48, row * 0.5 + 0.23, 0.6>, 0.15  material bore }}
    }}
  }}
}}
"""


def csg_wall(path, rows=25, cols=40, width=640, height=480):
    """rows x cols bricks in a running bond, each a difference of a box and a cylinder."""
    write(path, CSG_WALL.format(n=rows * cols, rows=rows, cols=cols, half=cols / 2, w=width, h=height))



# ---- the language of section 10: macros against the loops that made the same objects before ----

MACRO_SPHERES = """// a binary tree of {n} spheres made by a macro that calls itself twice, one sphere a call:
// level y holds the spheres x = 0 .. 2^y - 1 at <x, y, 0>
def tree(x, y, d) {{
  sphere {{ <x, y, 0>, 0.4 }}
  if d > 0 {{ tree(2 * x, y + 1, d - 1)  tree(2 * x + 1, y + 1, d - 1) }}
}}
tree(0, 0, {depth})
"""

LOOP_SPHERES = """// the {n} spheres of the macro tree, written with for loops as before macros: level y
// holds the spheres x = 0 .. 2^y - 1 at <x, y, 0>
for y in 0 .. {levels} {{
  for x in 0 .. pow(2, y) {{ sphere {{ <x, y, 0>, 0.4 }} }}
}}
"""


def sphere_tree(path, depth, macro):
    """2^(depth + 1) - 1 spheres in levels 0 .. depth, from a recursive macro (one sphere a
    call) or from nested for loops: the same spheres, in another order."""
    text = MACRO_SPHERES if macro else LOOP_SPHERES
    write(path, text.format(n=2 ** (depth + 1) - 1, depth=depth, levels=depth + 1))


MACRO_CALLS = """// {n} calls of a macro that makes one sphere, from a for loop
def ball(i) {{ sphere {{ <mod(i, 100), floor(i / 100), 0>, 0.4 }} }}
for i in 0 .. {n} {{ ball(i) }}
"""

INLINE_CALLS = """// the {n} spheres of the macro-call scene with the sphere written in the loop
for i in 0 .. {n} {{ sphere {{ <mod(i, 100), floor(i / 100), 0>, 0.4 }} }}
"""


def sphere_calls(path, n, macro):
    """n spheres from a loop, each from a call of a one-sphere macro or written inline."""
    write(path, (MACRO_CALLS if macro else INLINE_CALLS).format(n=n))


MACRO_TREE = """// a tree of {branches} branches, each a cylinder with a sphere at its joint, and {branches_half}
// leaves: a macro that calls itself twice a branch, turned and scaled by rand()
camera {{ location <0, 7.5, -25>  look_at <0, 7, 0>  fov 55  resolution {w}, {h} }}
light  {{ position <-14, 24, -18> }}
samples {{ count 5  pattern jittered }}
skybox {{ zenith <0.15, 0.3, 0.7>  horizon <0.75, 0.82, 0.9> }}
material ground {{ diffuse checker(<0.9, 0.9, 0.9>, <0.3, 0.3, 0.35>, 2) }}
material bark  {{ diffuse <0.45, 0.3, 0.2>  specular 0.1  shininess 20 }}
material leaf1 {{ diffuse <0.2, 0.6, 0.15>  specular 0.2  shininess 30 }}
material leaf2 {{ diffuse <0.5, 0.7, 0.1>  specular 0.2  shininess 30 }}
material leaf3 {{ diffuse <0.8, 0.45, 0.1>  specular 0.2  shininess 30 }}
plane {{ <0, 1, 0>, 0  material ground }}
let leaves = [leaf1, leaf2, leaf3]
// a unit vector at random, from the key k
def random_dir(k) = normalize(<rand(k) - 0.5, rand(k + 1) - 0.5, rand(k + 2) - 0.5>)
// a branch from base along dir (a unit vector), and below it two branches turned apart
// about a random axis across it; k numbers the branches as a heap does (children 2k, 2k + 1)
def branch(base, dir, len, r, d, k) {{
  let tip = base + dir * len
  cylinder {{ base, tip, r  material bark }}
  sphere {{ tip, r  material bark }}
  if d > 0 {{
    let side = normalize(cross(dir, random_dir(7 * k)))
    let spread = 0.55 + 0.5 * rand(7 * k + 3)
    branch(tip, normalize(dir + spread * side + <0, 0.25, 0>), len * (0.68 + 0.2 * rand(7 * k + 4)), r * 0.72,
           d - 1, 2 * k)
    branch(tip, normalize(dir - spread * side + <0, 0.25, 0>), len * (0.68 + 0.2 * rand(7 * k + 5)), r * 0.72,
           d - 1, 2 * k + 1)
  }} else {{
    let colour = leaves[floor(3 * rand(7 * k + 2))]
    sphere {{ tip, 0.09 + 0.05 * rand(7 * k + 6)  material colour }}
  }}
}}
branch(<0, 0, 0>, <0, 1, 0>, 3, 0.3, {depth}, 1)
"""


def macro_tree(path, depth=13, width=640, height=480):
    """A recursive tree of 2^(depth + 1) - 1 branches (a cylinder and a sphere each) and
    2^depth leaves (spheres): 5 * 2^depth - 2 objects, 40958 at depth 13."""
    branches = 2 ** (depth + 1) - 1
    write(path, MACRO_TREE.format(branches=branches, branches_half=2 ** depth, depth=depth, w=width, h=height))

# ---- surfaces (LANGUAGE.md section 11): the headline's spheres dressed in patterns ----

# (name, diffuse, plain twin's colour, the rest of the material); every sphere's diffuse is
# one of the ten patterns (four with turbulence), a few have bumps, one material in thirteen
# is an image map; the plain twin has each pattern's middle colour and no normal
SURFACES = [
    ("mirror", "pattern {{ granite  colors [[0, 0.02], [1, 0.1]] }}", "0.05",
     "specular 0.8  shininess 200  reflect 0.85"),
    ("glass", "pattern {{ bozo  colors [[0, 0], [1, 0.05]] }}", "0",
     "specular 0.6  shininess 300  reflect 0.08  transmit 0.9  ior 1.5  normal {{ waves 0.1  scale 0.3 }}"),
    ("grad", "pattern {{ gradient <0, 1, 0>  colors [[0, <0.8, 0.2, 0.15>], [1, <0.9, 0.9, 0.85>]]  scale 0.2 }}",
     "<0.85, 0.55, 0.5>", "specular 0.3  shininess 40"),
    ("radial", "pattern {{ radial  frequency 8  colors [[0, <0.9, 0.8, 0.1>], [1, <0.1, 0.4, 0.8>]] }}",
     "<0.5, 0.6, 0.45>", "specular 0.3  shininess 40"),
    ("onion", "pattern {{ onion  colors [[0, <0.2, 0.3, 0.8>], [1, <0.9, 0.85, 0.7>]]  scale 0.15 }}",
     "<0.55, 0.58, 0.75>", "specular 0.3  shininess 40  normal {{ bumps 0.4  scale 0.05 }}"),
    ("wood", "pattern {{ wood  turbulence 0.05  colors [[0, <0.55, 0.34, 0.16>], [1, <0.3, 0.17, 0.07>]]  scale 0.1 }}",
     "<0.42, 0.25, 0.11>", "specular 0.2  shininess 30"),
    ("marble", "pattern {{ marble  turbulence 0.8  colors [[0, <0.9, 0.9, 0.85>], [1, <0.3, 0.3, 0.35>]]  scale 0.3 }}",
     "<0.6, 0.6, 0.6>", "specular 0.4  shininess 80"),
    ("leopard", "pattern {{ leopard  colors [[0, <0.85, 0.6, 0.25>], [1, <0.2, 0.12, 0.05>]]  scale 0.05 }}",
     "<0.52, 0.36, 0.15>", "specular 0.1  shininess 20"),
    ("agate", "pattern {{ agate  colors [[0, <0.95, 0.9, 0.8>], [1, <0.35, 0.15, 0.15>]]  scale 0.3 }}",
     "<0.65, 0.52, 0.48>", "specular 0.5  shininess 100  normal {{ dents 0.5  scale 0.05 }}"),
    ("bozo", "pattern {{ bozo  turbulence 0.3  colors [[0, <0.2, 0.7, 0.25>], [1, <0.8, 0.7, 0.45>]]  scale 0.2 }}",
     "<0.5, 0.7, 0.35>", "specular 0.3  shininess 40"),
    ("granite", "pattern {{ granite  colors [[0, <0.75, 0.72, 0.7>], [1, <0.1, 0.1, 0.1>]] }}",
     "<0.42, 0.41, 0.4>", "specular 0.5  shininess 120  normal {{ wrinkles 0.3  scale 0.1 }}"),
    ("spotted", "pattern {{ spotted  turbulence 0.2  colors [[0, <0.2, 0.5, 0.3>], [1, <0.9, 0.95, 0.85>]]  scale 0.1 }}",
     "<0.55, 0.72, 0.58>", "specular 0.3  shininess 40  normal {{ ripples 0.3  scale 0.2 }}"),
    ("label", 'image {{ "{image}"  map spherical  interpolate bilinear }}', "<0.6, 0.45, 0.3>",
     "specular 0.3  shininess 40"),
]

SURFACES_SCENE = """// {what}
{setup}material floor {{ diffuse {floor}  reflect 0.1 }}
{materials}
plane {{ <0, 1, 0>, 0  material floor }}
{loops}"""


def surfaces(path, image, plain):
    """The headline's 1000 spheres and floor, every material a pattern (the floor marble), a
    few with bumps, one in thirteen an image map (image, an absolute path); or, plain, the
    exact twin: the same spheres and materials with plain colours and no normals."""
    mats = []
    for name, diffuse, colour, rest in SURFACES:
        if plain:
            rest = rest.split("  normal")[0]
        mats.append("material %s { diffuse %s  %s }" % (name, colour if plain else diffuse.format(image=image),
                                                         rest.format()))
    floor = ("<0.7, 0.7, 0.7>" if plain else
             "pattern { marble  turbulence 0.9  colors [[0, <0.92, 0.9, 0.86>], [0.8, <0.55, 0.55, 0.58>], "
             "[1, <0.3, 0.3, 0.34>]]  scale 2 }")
    what = ("plain: the textured scene's twin, every pattern and image a plain colour, no normals" if plain else
            "textured: 1000 spheres over a marble floor, each material one of the ten patterns (some with "
            "turbulence, some with bumps) or an image map")
    write(path, SURFACES_SCENE.format(what=what, setup=HEADLINE_SETUP.format(), floor=floor,
                                      materials="\n".join(mats),
                                      loops=sphere_loops(1000, [m[0] for m in SURFACES], HEADLINE_CENTRE,
                                                         HEADLINE_RADIUS)))


SHARED_IMAGE = """// {n} sphere(s), each with a material of its own that maps the same image file
camera {{ location <0, 0, -60>  look_at <0, 0, 0>  fov 60  resolution 64, 48 }}
light  {{ position <-10, 14, -30> }}
for i in 0 .. {n} {{
  sphere {{ <mod(i, 40) - 20, floor(i / 40) - 12, 0>, 0.4
           material {{ diffuse image {{ "{image}"  map spherical }} }} }}
}}
"""


def shared_image(path, image, n):
    """n spheres, each with its own inline material mapping the one image file."""
    write(path, SHARED_IMAGE.format(n=n, image=image))


def bunny(path, ply, example):
    """examples/bunny.scn with its mesh file replaced by ply (an absolute path), and 5 samples
    a pixel rather than 4: POV-Ray's +AM1 +R2 traces 5 camera rays, and none traces 4."""
    with open(example) as f:
        text = f.read()
    if "samples 4\n" not in text:
        sys.exit("bench: %s no longer has 'samples 4'" % example)
    text = text.replace("samples 4\n", "samples 5\n")
    write(path, text.replace('"bunny.ply"', '"' + os.path.abspath(ply) + '"'))


def write(path, text):
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


# ---- PLY: the bunny's binary little-endian float vertices and int triangle lists ----

def read_ply(path):
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    nv = nf = 0
    for line in header:
        w = line.split()
        if w[:2] == ["element", "vertex"]:
            nv = int(w[2])
        elif w[:2] == ["element", "face"]:
            nf = int(w[2])
    verts = list(struct.iter_unpack("<fff", data[end:end + 12 * nv]))
    faces, pos = [], end + 12 * nv
    for _ in range(nf):
        count = data[pos]
        faces.append(struct.unpack_from("<%di" % count, data, pos + 1))
        pos += 1 + 4 * count
    return verts, faces


def write_ply(path, verts, faces):
    head = ("ply\nformat binary_little_endian 1.0\ncomment bench/scenes.py: midpoint subdivision\n"
            f"element vertex {len(verts)}\nproperty float x\nproperty float y\nproperty float z\n"
            f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
    body = bytearray(head.encode("ascii"))
    for v in verts:
        body += struct.pack("<fff", *v)
    tri = struct.Struct("<Biii")
    for a, b, c in faces:
        body += tri.pack(3, a, b, c)
    write_bytes(path, bytes(body))


def write_bytes(path, data):
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    with open(path, "wb") as f:
        f.write(data)


def subdivide(verts, faces):
    """Midpoint subdivision: each triangle into four, edges split at their midpoints."""
    verts = list(verts)
    mid = {}

    def midpoint(a, b):
        key = (a, b) if a < b else (b, a)
        if key not in mid:
            pa, pb = verts[a], verts[b]
            verts.append(((pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, (pa[2] + pb[2]) / 2))
            mid[key] = len(verts) - 1
        return mid[key]

    out = []
    for a, b, c in faces:
        ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return verts, out


def bunny_subdivided(src, dst, target):
    """Writes src subdivided until it has at least target triangles (once: cached)."""
    if os.path.exists(dst):
        return
    verts, faces = read_ply(src)
    faces = [f for f in faces if len(f) == 3]
    while len(faces) < target:
        verts, faces = subdivide(verts, faces)
    write_ply(dst + ".tmp", verts, faces)
    os.replace(dst + ".tmp", dst)
