"""bench.py: scn's benchmarks, run by bench/run (see it for the options).

The scene table: scn and POV-Ray 3.7 on the same scenes, runs alternating scn/POV-Ray, the
median of each; POV-Ray renders the scene `scn pov` writes, with the command line written at
its top plus +WT2. The language: the load of 10^6 spheres from a recursive macro against the
same spheres from for loops, and the time of a macro call. Textures: the headline's spheres
in patterns, bumps and an image map against their plain twin, and the memory of one image
file that 1000 materials map. The scaling study: render time
against the number of spheres for each accelerator. The Embree table: bench/embree_compare. Scenes and meshes are generated into a
work folder (default /tmp/scn-bench), never committed."""

import argparse
import math
import os
import re
import shlex
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import scenes  # noqa: E402

SCN = os.path.join(TOP, "scn")
THREADS = 2
NONE_LIMIT = 60.0  # seconds: --accel none is not run where its render would take longer


def log(*args):
    print(*args, file=sys.stderr, flush=True)


def timed(cmd, cwd=None):
    """Runs cmd; returns (wall seconds, peak resident MB, stderr text). Fails loudly."""
    with tempfile.NamedTemporaryFile("r", suffix=".time") as tf:
        t0 = time.perf_counter()
        p = subprocess.run(["/usr/bin/time", "-f", "%M", "-o", tf.name] + cmd, cwd=cwd,
                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        wall = time.perf_counter() - t0
        if p.returncode != 0:
            sys.exit("bench: %s failed (status %d):\n%s" % (" ".join(cmd), p.returncode, p.stderr[-2000:]))
        kb = int(tf.read().split()[-1])
    return wall, kb / 1024, p.stderr


STATS_TIME = re.compile(r"^time: parse ([0-9.]+)s  check ([0-9.]+)s  evaluate ([0-9.]+)s  load meshes ([0-9.]+)s"
                        r"  load images ([0-9.]+)s  build \w+ ([0-9.]+)s  render ([0-9.]+)s  write ([0-9.]+)s$", re.M)
# "area shadow N (and M tests settled without one)" only for a scene with area lights
STATS_RAYS = re.compile(r"^rays: +camera (\d+) +shadow (\d+) +(?:area shadow (\d+) \(and \d+ tests settled without one\) +)?"
                        r"reflection (\d+) +refraction (\d+) +total (\d+)$", re.M)


def scn_stats(text):
    """load, build, render and write seconds and the rays by kind from --stats."""
    t, r = STATS_TIME.search(text), STATS_RAYS.search(text)
    if not t or not r:
        sys.exit("bench: no --stats in scn's output:\n" + text[-2000:])
    t = [float(x) for x in t.groups()]
    rays = dict(zip(["camera", "shadow", "area shadow", "reflection", "refraction", "total"],
                    (int(x or 0) for x in r.groups())))
    return {"load": t[0] + t[1] + t[2] + t[3] + t[4], "build": t[5], "render": t[6], "write": t[7], "rays": rays}


def scn_render(scene, out, accel="bvh"):
    wall, mb, err = timed([SCN, "render", scene, "-o", out, "-j", str(THREADS), "--accel", accel, "--stats",
                           "--no-progress"])
    return {"wall": wall, "mb": mb, **scn_stats(err)}


def pov_command(pov, spp):
    """The povray command line at the top of a .pov that scn pov wrote, with +WT2, its
    anti-aliasing set to trace as many camera rays a pixel as scn's spp do: with focal blur,
    the header's -A as it is, as the camera's blur_samples (scn's spp) are the rays a pixel."""
    with open(pov) as f:
        for line in f:
            if line.startswith("// Render: "):
                cmd = shlex.split(line[len("// Render: "):]) + ["+WT%d" % THREADS]
                return cmd if pov_blur_samples(pov) else equal_rays_aa(cmd, int(spp))
    sys.exit("bench: %s has no '// Render:' line" % pov)


def pov_blur_samples(pov):
    """The camera's blur_samples in a .pov that scn pov wrote, or 0 (no focal blur). POV-Ray
    traces exactly that many camera rays a pixel (its variance 0 never stops it early; its
    statistics count them in neither Pixels nor Samples) and with -A no more."""
    with open(pov) as f:
        m = re.search(r"^camera \{.* blur_samples (\d+)", f.read(), re.M)
    return int(m.group(1)) if m else 0


def equal_rays_aa(cmd, spp):
    """cmd with scn pov's +AM2 +Rd (a lattice whose edges neighbours share: 6.06 camera rays a
    pixel at d = 2 by POV-Ray's statistics, against scn's 5) replaced by +AM1 +Rn: the centre
    and n x n sub-samples, n^2 + 1 rays, for scn's spp = n^2 + 1 (jitter off, as scn pov has it)."""
    if spp <= 1:
        return cmd
    n = round(math.sqrt(spp - 1))
    if n * n + 1 != spp:
        sys.exit("bench: %d samples per pixel is not n^2 + 1; POV-Ray's +AM1 cannot trace as many" % spp)
    out = [a for a in cmd if not re.match(r"^(\+A[0-9.]*|\+AM\d|\+R\d+|-J)$", a)]
    return out[:2] + ["+A0.0", "+AM1", "+R%d" % n, "-J"] + out[2:]


POV_STATS = re.compile(r"^Pixels: +(\d+) +Samples: +(\d+)", re.M)


def pov_camera_rays(text, blur_samples=0):
    """POV-Ray's camera rays from its statistics: its pixels and its anti-aliasing samples, or
    with focal blur (and -A) blur_samples for each pixel."""
    m = POV_STATS.search(text)
    if not m:
        return float("nan")
    return int(m.group(1)) * blur_samples if blur_samples else int(m.group(1)) + int(m.group(2))


def median_run(runs):
    """The run whose wall time is the median (the lower middle for an even count)."""
    ordered = sorted(runs, key=lambda r: r["wall"])
    return ordered[(len(ordered) - 1) // 2]


# ---- the scene table ----

def make_scenes(work):
    """[(name, description, scene path)]: the five scenes of the issue, the solids of
    LANGUAGE.md section 9 (10^4 quadrics and tori, a wall of 1000 CSG bricks), the macros
    of section 10 (a tree of 40958 objects from a macro that calls itself), the surfaces
    of section 11 (the headline's spheres, textured), the lights and cameras of section 12,
    and issue 24's spheres of a material each, a third mirror and a third glass (the
    headline's 1000, and 10^5 in a box)."""
    bunny_ply = os.path.join(TOP, "examples", "bunny.ply")
    big_ply = os.path.join(work, "bunny-1m.ply")
    log("bench: writing scenes into", work)
    scenes.headline(os.path.join(work, "headline.scn"))
    scenes.field(os.path.join(work, "spheres-1e5.scn"), 100000)
    scenes.field(os.path.join(work, "spheres-1e6.scn"), 1000000)
    scenes.bunny(os.path.join(work, "bunny.scn"), bunny_ply, os.path.join(TOP, "examples", "bunny.scn"))
    scenes.bunny_subdivided(bunny_ply, big_ply, 900000)
    scenes.bunny(os.path.join(work, "bunny-1m.scn"), big_ply, os.path.join(TOP, "examples", "bunny.scn"))
    scenes.quadrics(os.path.join(work, "quadrics-1e4.scn"), 10000)
    scenes.csg_wall(os.path.join(work, "csg-wall.scn"))
    scenes.macro_tree(os.path.join(work, "macro-tree.scn"), 13)
    surfaces_scenes(work)
    scenes.soft_shadows(os.path.join(work, "soft-shadows.scn"))
    scenes.spotlights(os.path.join(work, "spotlights.scn"))
    scenes.fog(os.path.join(work, "fog.scn"))
    scenes.orthographic(os.path.join(work, "orthographic.scn"))
    scenes.focal_blur(os.path.join(work, "focal-blur.scn"))
    scenes.mirrors(os.path.join(work, "mirrors.scn"))
    scenes.dense_mirrors(os.path.join(work, "dense-mirrors.scn"))
    return [("headline", "1000 spheres, mirror+glass, 2 lights", "headline.scn"),
            ("spheres 1e5", "100000 spheres, 1 light", "spheres-1e5.scn"),
            ("spheres 1e6", "1000000 spheres, 1 light", "spheres-1e6.scn"),
            ("bunny", "examples/bunny.ply, 3674 triangles", "bunny.scn"),
            ("bunny 1M", "bunny, midpoint-subdivided x4: 940544 triangles", "bunny-1m.scn"),
            ("quadrics 1e4", "10000 boxes, cylinders, cones, ellipsoids, tori (2000 each), 1 light", "quadrics-1e4.scn"),
            ("csg wall", "1000 bricks, each a difference of a box and a cylinder, 1 light", "csg-wall.scn"),
            ("macro tree", "a macro calling itself twice, turned by rand(): 16383 cylinders, 24575 spheres, "
             "1 light", "macro-tree.scn"),
            ("textured", "the headline's spheres in the ten patterns (some turbulent, some bumped) and an image "
             "map, a marble floor", "textured.scn"),
            ("soft shadows", "150 spheres and 150 boxes on a floor under one area light 8 x 8, jittered",
             "soft-shadows.scn"),
            ("spotlights", "the headline's spheres under four spotlights with fade", "spotlights.scn"),
            ("fog", "the headline with fog (distance 18)", "fog.scn"),
            ("orthographic", "the headline's spheres from above through an orthographic camera", "orthographic.scn"),
            ("focal blur", "the headline through a lens (aperture 0.6; POV-Ray: blur_samples 5 and -A, 5 rays "
             "a pixel as scn's 5 samples)", "focal-blur.scn"),
            ("mirrors", "the headline's 1000 spheres, each its own material, a third mirror, a third glass",
             "mirrors.scn"),
            ("dense mirrors", "100000 spheres in a box, each its own material, a third mirror, a third glass, "
             "max_depth 8", "dense-mirrors.scn")]


def scene_settings(path):
    """(width x height, samples, depth) as scn renders the scene (scn check --dump)."""
    p = subprocess.run([SCN, "check", "--dump", path], capture_output=True, text=True)
    text = p.stdout
    res = re.search(r"resolution (\d+) (\d+)", text)
    spp = re.search(r"samples count (\d+)", text)
    depth = re.search(r"max_depth (\d+)", text)
    return ("%sx%s" % res.groups() if res else "?", spp.group(1) if spp else "1", depth.group(1) if depth else "5")


def image_rmse(a, b):
    """scn diff's RMSE between the two renders, in linear light: that both drew the same picture."""
    p = subprocess.run([SCN, "diff", a, b], capture_output=True, text=True)
    m = re.search(r"^rmse ([0-9.e+-]+)", p.stdout, re.M)
    return float(m.group(1)) if m else float("nan")


def scene_table(work, runs, table_scenes, only=None):
    """only: the names of the scenes to run (None: every one)."""
    rows = []
    for name, what, file in table_scenes:
        if only and name not in only:
            continue
        scene = os.path.join(work, file)
        pov = os.path.join(work, file[:-4] + ".pov")
        subprocess.run([SCN, "pov", scene, "-o", pov], check=True, stderr=subprocess.DEVNULL)
        settings = scene_settings(scene)
        cmd = pov_command(pov, settings[1])
        blur = pov_blur_samples(pov)
        s_runs, p_runs = [], []
        for i in range(runs):
            log("bench: %s: run %d of %d: scn, then POV-Ray" % (name, i + 1, runs))
            s_runs.append(scn_render(scene, os.path.join(work, file[:-4] + "-scn.png")))
            wall, mb, err = timed(cmd, cwd=work)
            p_runs.append({"wall": wall, "mb": mb, "camera": pov_camera_rays(err, blur)})
        s_med = median_run(s_runs)
        s_med["rmse"] = image_rmse(os.path.join(work, file[:-4] + "-scn.png"), os.path.join(work, file[:-4] + "-pov.png"))
        rows.append((name, what, settings, s_med, median_run(p_runs),
                     max(r["mb"] for r in s_runs), max(r["mb"] for r in p_runs), cmd))
    return rows


def print_scene_table(rows, runs):
    print("scn against POV-Ray 3.7: wall time, median of %d alternating runs (scn, POV-Ray, scn, ...); "
          "scn -j %d, POV-Ray +WT%d;" % (runs, THREADS, THREADS))
    print("same resolution, camera rays per pixel and max_depth (scn pov writes the scene). scn's 5 samples "
          "a pixel are jittered;")
    print("POV-Ray cannot place them and traces +A0.0 +AM1 +R2 -J instead: the centre and a 2x2 grid, 5 rays. "
          "1 spp scenes: one ray")
    print("through each pixel centre in both. rays/px: camera rays per pixel as each counts them (scn --stats; "
          "POV-Ray's Pixels + Samples).")
    print()
    head = ("%-12s %-10s %3s %5s | %6s %6s | %7s %7s %7s | %7s %7s | %6s %6s %7s | %6s" %
            ("scene", "size", "spp", "depth", "scn", "pov", "scn s", "pov s", "pov/scn", "scn MB", "pov MB", "load",
             "build", "render", "RMSE"))
    print("%-12s %-10s %3s %5s | %13s |" % ("", "", "", "", "rays/px"))
    print(head)
    print("-" * len(head))
    for name, what, (size, spp, depth), s, p, smb, pmb, _ in rows:
        npix = math.prod(int(x) for x in size.split("x"))
        print("%-12s %-10s %3s %5s | %6.2f %6.2f | %7.2f %7.2f %6.1fx | %7.0f %7.0f | %6.2f %6.2f %7.2f | %6.4f" %
              (name, size, spp, depth, s["rays"]["camera"] / npix, p["camera"] / npix, s["wall"], p["wall"],
               p["wall"] / s["wall"], smb, pmb, s["load"], s["build"], s["render"], s["rmse"]))
    print()
    print("pov/scn: how many times faster scn is. MB: peak resident memory. load (parse, evaluate, read meshes), "
          "build (BVH)")
    print("and render: scn's phases (--stats). RMSE: scn diff between the two images, in linear light "
          "(sampling noise; the same picture).")
    print()
    print("scn's rays per second by kind during its render phase (Mrays/s; the median run's --stats):")
    head = "%-12s %9s %9s %12s %11s %11s %9s" % ("scene", "camera", "shadow", "area shadow", "reflection",
                                                 "refraction", "total")
    print(head)
    print("-" * len(head))
    for name, _, _, s, _, _, _, _ in rows:
        r = s["rays"]
        rate = lambda k: "%.2f" % (r[k] / s["render"] * 1e-6) if r[k] else "-"
        print("%-12s %9s %9s %12s %11s %11s %9s" % (name, rate("camera"), rate("shadow"), rate("area shadow"),
                                                    rate("reflection"), rate("refraction"), rate("total")))
    print()
    print("scenes:")
    for name, what, _, _, _, _, _, cmd in rows:
        print("  %-12s %s" % (name, what))
    print("POV-Ray's command for %s: " % rows[0][0] + " ".join(rows[0][7]))


# ---- the language: macros against the for loops scn had before them ----

# The targets: 10^6 objects from a recursive macro load in at most LANG_TARGET times
# the time of the same objects from for loops, and a scene of 10^5 macro calls is reported
# per call.
LANG_TARGET = 1.5
TREE_DEPTH = 19  # levels 0 .. 19: 2^20 - 1 = 1048575 spheres, one a call
CALLS = 100000
# These loads take 0.02 to 0.3 s, which one of this machine's slow spells moves by half: each
# scene runs at least the runs asked for and until it has taken LANG_WALL seconds in all, up
# to LANG_MAX_RUNS runs, the two of a pair taking turns (and turns at going first).
LANG_WALL = 4.0
LANG_MAX_RUNS = 25
# A run of the 10^5-call scenes evaluates them CALL_FRAMES times in one process (--frames): the
# first is the load, as the tree's; the others, in memory the first left warm, measure the
# evaluation itself. --stats gives a phase to the millisecond, 10 ns a call: the evaluations'
# interquartile mean, over many, resolves less than that (a median stays on the milliseconds).
CALL_FRAMES = 20

STATS_EVAL = re.compile(r"^evaluation: (\d+) steps, (\d+) calls", re.M)
STATS_SCENE = re.compile(r"^scene: (\d+) spheres, (\d+) planes, (\d+) triangles, (\d+) solids", re.M)


def scn_load(scene, out, frames=1):
    """One process's loads of the scene: for each frame, --stats' parse + check + evaluate (their
    sum is the exact clock's); the evaluation's steps and calls, the objects, and the process's
    CPU seconds (user + sys). The render after a load is one pixel, --accel none, one thread:
    what follows the load costs little, and the same for two scenes of the same objects."""
    cmd = [SCN, "render", scene, "-o", out, "-W", "1", "-H", "1", "-j", "1", "--accel", "none", "--stats",
           "--no-progress"] + (["--frames", "0..%d" % frames] if frames > 1 else [])
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    err = p.stderr.read()
    _, status, ru = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    if p.returncode != 0:
        sys.exit("bench: %s failed (status %d):\n%s" % (" ".join(cmd), p.returncode, err[-2000:]))
    loads = [sum(float(x) for x in t.groups()[:3]) for t in STATS_TIME.finditer(err)]
    e, n = STATS_EVAL.search(err), STATS_SCENE.search(err)
    if len(loads) != frames or not e or not n:
        sys.exit("bench: no --stats in scn's output:\n" + err[-2000:])
    return {"load": loads[0], "again": loads[1:], "steps": int(e.group(1)), "calls": int(e.group(2)),
            "objects": int(n.group(1)) + int(n.group(2)) + int(n.group(3)) + int(n.group(4)),
            "cpu": ru.ru_utime + ru.ru_stime}


def load_pair(a, b, out, runs, frames=1):
    """Runs of scenes a and b taking turns: ([runs of a], [runs of b])."""
    ra, rb = [], []
    spent = lambda: sum(r["load"] + sum(r["again"]) for r in ra + rb)
    while len(ra) < runs or (spent() < 2 * LANG_WALL and len(ra) < LANG_MAX_RUNS):
        log("bench: language: %s and %s, run %d" % (os.path.basename(a), os.path.basename(b), len(ra) + 1))
        if len(ra) % 2 == 0:
            ra.append(scn_load(a, out, frames))
            rb.append(scn_load(b, out, frames))
        else:
            rb.append(scn_load(b, out, frames))
            ra.append(scn_load(a, out, frames))
    return ra, rb


def dumped_objects(scene):
    """scn check --dump's object lines without their index, sorted (the objects, whatever order
    made them), and its other lines in order."""
    p = subprocess.run([SCN, "check", "--dump", scene], capture_output=True)
    if p.returncode != 0:
        sys.exit("bench: scn check --dump %s failed:\n%s" % (scene, p.stderr.decode()[-2000:]))
    others, objects = [], []
    for line in p.stdout.split(b"\n"):
        kind, _, rest = line.partition(b" ")
        index, _, rest = rest.partition(b" ")
        if index.isdigit() and rest:  # "sphere 12 center ...", not "max_depth 5"
            objects.append(kind + b" " + rest)
        else:
            others.append(line)
    objects.sort()
    return others, objects


def same_objects(a, b):
    """The number of objects if scenes a and b make the same ones (the same dump, but for the
    objects' order), else exits: the comparison of their loads would mean nothing."""
    da = dumped_objects(a)
    if da != dumped_objects(b):
        sys.exit("bench: %s and %s do not make the same objects (scn check --dump)" % (a, b))
    return len(da[1])


def language(work, runs):
    """{"tree": (macro runs, loops runs), "calls": (macro runs, inline runs)}, and the
    objects' counts, checked the same in each pair."""
    paths = {}
    for name, write in (("tree-macro", lambda p: scenes.sphere_tree(p, TREE_DEPTH, True)),
                        ("tree-loops", lambda p: scenes.sphere_tree(p, TREE_DEPTH, False)),
                        ("calls-macro", lambda p: scenes.sphere_calls(p, CALLS, True)),
                        ("calls-inline", lambda p: scenes.sphere_calls(p, CALLS, False))):
        paths[name] = os.path.join(work, name + ".scn")
        write(paths[name])
    log("bench: language: comparing the objects (scn check --dump)")
    same = {"tree": same_objects(paths["tree-macro"], paths["tree-loops"]),
            "calls": same_objects(paths["calls-macro"], paths["calls-inline"])}
    frames_dir = os.path.join(work, "language-frames")
    os.makedirs(frames_dir, exist_ok=True)
    result = {"tree": load_pair(paths["tree-macro"], paths["tree-loops"], os.path.join(work, "language.png"), runs),
              "calls": load_pair(paths["calls-macro"], paths["calls-inline"], os.path.join(frames_dir, "f.png"), runs,
                                 CALL_FRAMES)}
    return result, same


def interquartile_mean(xs):
    xs = sorted(xs)
    q = len(xs) // 4
    return statistics.mean(xs[q:len(xs) - q])


def print_language(result, same, runs):
    med = lambda rs, k: statistics.median(r[k] for r in rs)
    print("the language of LANGUAGE.md section 10: load = parse + check + evaluate (scn render --stats; "
          "1 pixel, --accel none, -j 1),")
    print("a process each; the two scenes of a pair take turns, at least %d runs each and until the pair has "
          "taken %.0f s, up to %d runs." % (runs, 2 * LANG_WALL, LANG_MAX_RUNS))
    print("cpu s: the whole process's user + sys seconds (its start, loads, the scene's arrays, pixels, exit), "
          "which differ in a pair only")
    print("by the loads; the calls' runs load their scene %d times each (--frames; the load s columns: the "
          "first)." % CALL_FRAMES)
    print()
    head = "%-13s %8s %8s %9s %5s | %8s %8s %8s | %7s" % ("scene", "objects", "calls", "steps", "runs", "load s",
                                                        "min s", "max s", "cpu s")
    print(head)
    print("-" * len(head))
    names = {"tree": ("tree macro", "tree loops"), "calls": ("calls macro", "calls inline")}
    for pair in ("tree", "calls"):
        for name, rs in zip(names[pair], result[pair]):
            print("%-13s %8d %8d %9d %5d | %8.3f %8.3f %8.3f | %7.3f" %
                  (name, rs[0]["objects"], rs[0]["calls"], rs[0]["steps"], len(rs), med(rs, "load"),
                   min(r["load"] for r in rs), max(r["load"] for r in rs), med(rs, "cpu")))
    print()
    ra, rb = result["tree"]
    ratio = med(ra, "load") / med(rb, "load")
    paired = statistics.median(a["load"] / b["load"] for a, b in zip(ra, rb))
    fast = min(r["load"] for r in ra) / min(r["load"] for r in rb)
    print("tree macro: %d spheres from one call each of def tree(x, y, d), the same objects as tree loops' "
          "(sorted dumps equal):" % same["tree"])
    print("its load takes %.2fx the loops' (the medians; the median of the ratios run by run %.2fx, the fastest "
          "runs' %.2fx):" % (ratio, paired, fast))
    print("target %.1fx, %s; %.0f ns a call, %.0f ns a sphere more than the loops'" %
          (LANG_TARGET, "met" if ratio <= LANG_TARGET else "missed by %.0f%%" % (100 * (ratio / LANG_TARGET - 1)),
           med(ra, "load") / ra[0]["calls"] * 1e9, (med(ra, "load") - med(rb, "load")) / same["tree"] * 1e9))
    ca, cb = result["calls"]
    calls = ca[0]["calls"]
    again = [interquartile_mean([x for r in rs for x in r["again"]]) for rs in (ca, cb)]
    count = len(ca) * (CALL_FRAMES - 1)
    print("calls macro: %d calls of def ball(i), one sphere each, the same objects as calls inline's: a load "
          "%.0f ns a call (the median)," % (calls, med(ca, "load") / calls * 1e9))
    print("%.0f ns more than the inline sphere's; evaluated again in the same process (%d times, the interquartile "
          "mean) %.0f ns a call," % ((med(ca, "load") - med(cb, "load")) / calls * 1e9, count, again[0] / calls * 1e9))
    print("inline %.0f ns a sphere: a call's own cost %.1f ns (by the processes' cpu medians, %.1f ns)" %
          (again[1] / calls * 1e9, (again[0] - again[1]) / calls * 1e9,
           (med(ca, "cpu") - med(cb, "cpu")) / (CALL_FRAMES * calls) * 1e9))


# ---- surfaces: the cost of patterns, image maps and bumps, and one image in memory ----

# The targets: the textured scene renders in at most TEXTURE_TARGET times the time of
# its plain twin, and an image file that many materials map is held once.
TEXTURE_TARGET = 1.3
SHARED_N = 1000
SHARED_IMAGE_SIZE = 1024  # the shared image's side in pixels: its texels are megabytes


def surfaces_scenes(work):
    """Writes textured.scn and plain.scn into work; returns their paths. The image map is
    examples/crate.png."""
    image = os.path.join(TOP, "examples", "crate.png")
    paths = os.path.join(work, "textured.scn"), os.path.join(work, "plain.scn")
    scenes.surfaces(paths[0], image, False)
    scenes.surfaces(paths[1], image, True)
    return paths


def png_size(path):
    """(width, height) from a PNG's IHDR."""
    with open(path, "rb") as f:
        head = f.read(24)
    return int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")


def textures(work, runs):
    """The textured scene against its plain twin, runs of each taking turns (and turns at going
    first); and the peak RSS of SHARED_N spheres whose materials map one image file against one
    sphere that maps it."""
    textured, plain = surfaces_scenes(work)
    out = os.path.join(work, "textures.png")
    rt, rp = [], []
    for i in range(runs):
        log("bench: textures: textured and plain, run %d of %d" % (i + 1, runs))
        order = [(textured, rt), (plain, rp)] if i % 2 == 0 else [(plain, rp), (textured, rt)]
        for scene, rs in order:
            rs.append(scn_render(scene, out))
    image = os.path.join(work, "shared-image.png")
    if not os.path.exists(image):
        log("bench: textures: drawing a %d x %d image from examples/crate-texture.scn" %
            (SHARED_IMAGE_SIZE, SHARED_IMAGE_SIZE))
        subprocess.run([SCN, "render", os.path.join(TOP, "examples", "crate-texture.scn"), "-o", image,
                        "-W", str(SHARED_IMAGE_SIZE), "-H", str(SHARED_IMAGE_SIZE), "-s", "1", "-q"], check=True)
    mem = {}
    for n in (1, SHARED_N):
        scene = os.path.join(work, "shared-image-%d.scn" % n)
        scenes.shared_image(scene, image, n)
        mbs = []
        for i in range(runs):
            log("bench: textures: %d sphere(s) mapping one image, run %d of %d" % (n, i + 1, runs))
            mbs.append(scn_render(scene, out)["mb"])
        mem[n] = statistics.median(mbs)
    return rt, rp, mem, png_size(image), horizon(work)


HORIZON = """// horizon: a floor image-mapped to the horizon (examples/crate.png, repeating), the
// aliasing that texture lookups without filtering show at a few samples a pixel
camera {{ location <0, 1, -4>  look_at <0, 0.6, 10>  fov 60  resolution 320, 240 }}
light  {{ direction <0.3, -1, 0.5> }}
skybox {{ color <0.5, 0.6, 0.8> }}
samples {{ count 5  pattern jittered }}
plane {{ <0, 1, 0>, 0  material {{ diffuse image {{ "{image}"  map planar  rotate <90, 0, 0>  scale 0.5 }} }} }}
"""
HORIZON_REFERENCE_SPP = 1024


def horizon(work):
    """The RMSE against a reference of HORIZON_REFERENCE_SPP samples a pixel (scn's: planar
    image maps agree with POV-Ray to 2.4e-5, so it is POV-Ray's reference too) of scn at 5
    samples a pixel and of POV-Ray at 5 camera rays a pixel, and scn's own estimate."""
    scene = os.path.join(work, "horizon.scn")
    scenes.write(scene, HORIZON.format(image=os.path.join(TOP, "examples", "crate.png")))
    ref, mine = os.path.join(work, "horizon-ref.png"), os.path.join(work, "horizon-scn.png")
    log("bench: textures: the horizon's reference, %d samples a pixel" % HORIZON_REFERENCE_SPP)
    subprocess.run([SCN, "render", scene, "-o", ref, "-s", str(HORIZON_REFERENCE_SPP), "--bit-depth", "16", "-q"],
                   check=True)
    p = subprocess.run([SCN, "render", scene, "-o", mine, "--bit-depth", "16"], check=True, capture_output=True,
                       text=True)
    m = re.search(r"estimated RMSE ([0-9.e+-]+)", p.stderr)
    pov = os.path.join(work, "horizon.pov")
    subprocess.run([SCN, "pov", scene, "-o", pov], check=True, stderr=subprocess.DEVNULL)
    subprocess.run(pov_command(pov, 5), cwd=work, check=True, capture_output=True)
    return (image_rmse(mine, ref), float(m.group(1)) if m else float("nan"),
            image_rmse(os.path.join(work, "horizon-pov.png"), ref))


def print_textures(rt, rp, mem, size, aliasing, runs):
    med = lambda rs, k: statistics.median(r[k] for r in rs)
    s = rt[0]
    print("surfaces (LANGUAGE.md section 11): textured, the headline's 1000 spheres and floor with every pigment a "
          "pattern (the ten,")
    print("some turbulent), bumps on some and an image map on one material in thirteen, against plain, its twin with "
          "plain colours and")
    print("no normals; 1280x1024, 5 spp, -j %d; %d runs of each, the two taking turns; the medians" % (THREADS, runs))
    print()
    head = "%-9s | %8s %8s %8s | %7s" % ("scene", "wall s", "render s", "min s", "Mrays/s")
    print(head)
    print("-" * len(head))
    for name, rs in (("textured", rt), ("plain", rp)):
        rays = statistics.median(r["rays"]["total"] / r["render"] for r in rs) * 1e-6
        print("%-9s | %8.2f %8.2f %8.2f | %7.2f" % (name, med(rs, "wall"), med(rs, "render"),
                                                   min(r["render"] for r in rs), rays))
    print()
    ratio = med(rt, "render") / med(rp, "render")
    same = all(r["rays"] == s["rays"] for r in rt) and all(r["rays"] == rp[0]["rays"] for r in rp)
    print("textured over plain, render phase: %.2fx (wall %.2fx); target %.1fx, %s" %
          (ratio, med(rt, "wall") / med(rp, "wall"), TEXTURE_TARGET,
           "met" if ratio <= TEXTURE_TARGET else "missed by %.0f%%" % (100 * (ratio / TEXTURE_TARGET - 1))))
    print("rays: textured %d, plain %d (bumps bend the reflected and refracted rays: the counts differ a little)%s" %
          (s["rays"]["total"], rp[0]["rays"]["total"], "" if same else "; the counts varied between runs"))
    w, h = size
    texels = w * h * 3 * 4 / 2 ** 20
    print()
    print("one image file, %d x %d pixels (%.0f MB as float RGB), mapped by the material of each of n spheres, "
          "64x48, 1 spp:" % (w, h, texels))
    print("peak RSS, the median of %d runs: n = 1: %.1f MB, n = %d: %.1f MB, a difference of %.1f MB; %d copies "
          "would be %.0f MB more" % (runs, mem[1], SHARED_N, mem[SHARED_N], mem[SHARED_N] - mem[1], SHARED_N,
                                     (SHARED_N - 1) * texels))
    print()
    scn_rmse, estimate, pov_rmse = aliasing
    print("aliasing: a floor image-mapped to the horizon (bench's horizon.scn, 320x240), its RMSE against %d samples "
          "a pixel:" % HORIZON_REFERENCE_SPP)
    print("scn at 5 jittered samples %.4f (its own estimate %.4f), POV-Ray at 5 camera rays (+AM1 +R2) %.4f: "
          "scn's is %.2fx POV-Ray's" % (scn_rmse, estimate, pov_rmse, scn_rmse / pov_rmse))


# ---- the scaling study ----

SCALING_N = [10, 100, 1000, 10000, 100000, 1000000]
ACCELS = [("bvh", "#1f77b4", "solid"), ("grid", "#2ca02c", "solid"), ("none", "#d62728", "dashed")]
ACCEL_NAMES = {"bvh": "--accel bvh", "grid": "--accel grid", "none": "--accel none"}


# The scaling study's render phases at small N last 20-50 ms, which one of this machine's
# slow spells moved by half in a median of three (10^3 spheres: 0.035 s in one full run,
# 0.051 s in the next): such configurations run until they have taken SCALING_WALL seconds
# in all, up to SCALING_MAX_RUNS runs.
SCALING_WALL = 2.0
SCALING_MAX_RUNS = 15


def scaling(work, runs):
    """{(n, accel): the median of each phase over the runs, and the runs' count}"""
    table = {}
    none_last = None  # (n, render seconds) of the last none run
    for n in SCALING_N:
        scene = os.path.join(work, "field-%d.scn" % n)
        scenes.field(scene, n)
        for accel, _, _ in ACCELS:
            if accel == "none" and none_last and none_last[1] * n / none_last[0] > NONE_LIMIT:
                continue  # brute force grows as n: this one would pass the limit
            ms = []
            while len(ms) < runs or (sum(m["wall"] for m in ms) < SCALING_WALL and len(ms) < SCALING_MAX_RUNS):
                log("bench: scaling: %d spheres, --accel %s, run %d" % (n, accel, len(ms) + 1))
                ms.append(scn_render(scene, os.path.join(work, "field.png"), accel))
            table[(n, accel)] = {k: statistics.median(m[k] for m in ms) for k in ("render", "load", "build")}
            table[(n, accel)]["runs"] = len(ms)
            if accel == "none":
                none_last = (n, table[(n, accel)]["render"])
    return table


def print_scaling(table, runs):
    counts = ", ".join("%d" % table[(n, "bvh")]["runs"] for n in SCALING_N)
    print("render time against the number of spheres: 640x480, 1 spp, 1 light, spheres at random in a box "
          "filling 3%% of it; -j %d; each phase's median over %d runs or more (a configuration runs until "
          "it has taken %.0f s, up to %d runs; the bvh's: %s)" % (THREADS, runs, SCALING_WALL, SCALING_MAX_RUNS,
                                                                 counts))
    print("(render: the render phase of --stats; setup: parse, evaluate and build the accelerator; "
          "none is left out where it would pass %.0f s)" % NONE_LIMIT)
    print("%9s | %s" % ("", " | ".join("%-16s" % ("--accel " + a) for a, _, _ in ACCELS)))
    head = "%9s | %s" % ("spheres", " | ".join("%8s %7s" % ("render", "setup") for _ in ACCELS))
    print(head)
    print("-" * len(head))
    for n in SCALING_N:
        cells = []
        for accel, _, _ in ACCELS:
            m = table.get((n, accel))
            cells.append("%8.3f %7.3f" % (m["render"], m["load"] + m["build"]) if m else "%8s %7s" % ("-", "-"))
        print("%9d | %s" % (n, " | ".join(cells)))
    b = lambda n: table[(n, "bvh")]["render"]
    print("bvh render time, 1e6 spheres over 1e3: %.2fx" % (b(1000000) / b(1000)))


def plot_scaling(table, svg):
    subprocess.run(["make", "-s", "-C", TOP, "bench/plot_csv"], check=True, stdout=subprocess.DEVNULL)
    lines = ["title scn render time against scene size (640x480, 1 spp, -j %d)" % THREADS,
             "subtitle N spheres at random in a box; the render phase only (--stats), not parse or build",
             "xlabel spheres", "ylabel render time (s)"]
    for accel, color, style in ACCELS:
        lines.append("series %s %s %s" % (color, style, ACCEL_NAMES[accel]))
        lines += ["%d %.6f" % (n, table[(n, accel)]["render"]) for n in SCALING_N if (n, accel) in table]
    p = subprocess.run([os.path.join(TOP, "bench", "plot_csv")], input="\n".join(lines) + "\n", text=True,
                       capture_output=True, check=True)
    with open(svg, "w") as f:
        f.write(p.stdout)


# ---- Embree ----

def embree(work):
    make = subprocess.run(["make", "-s", "-C", TOP, "bench/embree_compare"], capture_output=True, text=True)
    if make.returncode != 0:
        print("Embree comparison not run: bench/embree_compare did not build:\n" + make.stderr[-1500:])
        return
    print("raw traversal, scn's BVH against Embree 3 (rtcIntersect1, default build quality), the same "
          "triangles and rays, median of 5 passes each, the two taking turns:")
    sys.stdout.flush()
    subprocess.run([os.path.join(TOP, "bench", "embree_compare"), os.path.join(work, "bunny.scn"),
                    os.path.join(work, "bunny-1m.scn")], check=True)
    print("the spheres of the scaling study (Embree: its sphere points, in float), camera rays, 1 thread: the "
          "traversal's part of the scaling study, without shading or shadow rays:")
    sys.stdout.flush()
    fields = []
    for n in (1000, 10000, 100000, 1000000):
        fields.append(os.path.join(work, "field-%d.scn" % n))
        scenes.field(fields[-1], n)
    p = subprocess.run([os.path.join(TOP, "bench", "embree_compare"), "--scaling"] + fields, check=True,
                       capture_output=True, text=True)
    print(p.stdout, end="")
    rate = {}
    for line in p.stdout.splitlines()[1:]:
        f = line.split()
        rate[int(f[1])] = (float(f[2]), float(f[3]))
    print("time per camera ray, 10^6 spheres over 10^3: scn %.2fx, Embree %.2fx"
          % (rate[1000][0] / rate[1000000][0], rate[1000][1] / rate[1000000][1]))


CONVERGE_BUDGET = 300  # seconds, for each scene


def converge(work, only=None):
    """scn converge on examples/whitted.scn, and on a few spheres and boxes under a jittered 8 x 8
    area light (POV-Ray then at each area_light adaptive level too), the plot of the latter into
    examples/soft-converge.svg. only: the names of the scenes to run ("whitted", "soft shadows")."""
    soft = os.path.join(work, "soft-converge.scn")
    scenes.soft_shadows(soft, n=3, width=320, height=240, samples=0)
    for name, scene, extra in (("whitted", os.path.join(TOP, "examples", "whitted.scn"), []),
                               ("soft shadows", soft, ["--plot", os.path.join(TOP, "examples", "soft-converge.svg")])):
        if only and name not in only:
            continue
        log("bench: scn converge %s --budget %d (about %d minutes)" % (name, CONVERGE_BUDGET, CONVERGE_BUDGET // 60))
        p = subprocess.run([SCN, "converge", scene, "--budget", str(CONVERGE_BUDGET), "-j", str(THREADS)] + extra,
                           capture_output=True, text=True, check=True)
        shown = os.path.relpath(scene, TOP) if scene.startswith(TOP) else "bench's " + os.path.basename(scene)
        if extra:
            print("scn converge %s --budget %d:" % (shown, CONVERGE_BUDGET))
            print(p.stdout, end="")
        print("scn converge %s --budget %d, its last line: %s" % (shown, CONVERGE_BUDGET,
                                                                  p.stdout.strip().splitlines()[-1]))


# ---- Over processes (MPI) ----

DIST_PROCESSES = 2  # this machine's cores: 2 processes x 1 thread against 1 process x 2 threads
STATS_TRAFFIC = re.compile(r"^processes: (\d+); (\d+) of (\d+) tiles from the others in (\d+) messages, (\d+) bytes "
                           r"\((\d+) a tile\); gathering them took ([0-9.]+)s$", re.M)


def mpirun(np, cmd):
    env = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1".split() if os.getuid() == 0 else []
    return ["env"] + env + ["mpirun", "--oversubscribe", "--mca", "btl", "self,vader", "-np", str(np)] + cmd


def distributed(work, runs):
    """Each scene (the headline, 1280x1024, 4 spp; the same with its cost in one corner) on
    one process of 2 threads and on 2 processes of 1 thread, in turn, run after run; and a
    1-pixel render with and without mpirun."""
    rows = []
    for name, make in (("headline", scenes.headline), ("corner", scenes.corner)):
        scene = os.path.join(work, name + ".scn")
        make(scene)
        out = os.path.join(work, "dist.png")
        base = [SCN, "render", scene, "-o", out, "-s", "4", "--stats", "--no-progress"]
        one, many, traffic = [], [], None
        for r in range(runs):
            log("bench: processes: %s, run %d" % (name, r + 1))
            one.append(timed(base + ["-j", str(DIST_PROCESSES)]))
            many.append(timed(mpirun(DIST_PROCESSES, base + ["-j", "1"])))
            traffic = STATS_TRAFFIC.search(many[-1][2])
        rows.append((name, one, many, traffic))
    tiny = os.path.join(work, "tiny.scn")
    with open(tiny, "w") as f:
        f.write("camera { location <0, 0, -5>  look_at <0, 0, 0>  resolution 1, 1 }\nsphere { <0, 0, 0>, 1 }\n")
    out = os.path.join(work, "tiny.png")
    start_plain = [timed([SCN, "render", tiny, "-o", out, "-q"])[0] for _ in range(max(runs, 5))]
    start_mpi = [timed(mpirun(DIST_PROCESSES, [SCN, "render", tiny, "-o", out, "-q"]))[0] for _ in range(max(runs, 5))]
    return rows, start_plain, start_mpi


def print_distributed(rows, start_plain, start_mpi, runs):
    med = lambda xs, f: statistics.median(f(x) for x in xs)
    render = lambda t: scn_stats(t[2])["render"]
    print("over processes: 1280x1024, 4 spp; median of %d runs, taken in turn; render is --stats's phase on "
          "process 0, wall includes mpirun" % runs)
    for name, one, many, traffic in rows:
        r1, rn = med(one, render), med(many, render)
        w1, wn = med(one, lambda t: t[0]), med(many, lambda t: t[0])
        print("  %-8s 1 process x %d threads:  render %.3f s, wall %.3f s" % (name, DIST_PROCESSES, r1, w1))
        print("  %-8s %d processes x 1 thread: render %.3f s, wall %.3f s" % (name, DIST_PROCESSES, rn, wn))
        print("  %-8s MPI overhead: render %+.1f%%, wall %+.1f%%" % (name, 100 * (rn / r1 - 1), 100 * (wn / w1 - 1)))
        if traffic:
            n, tiles, total, msgs, nbytes, per, gather = traffic.groups()
            print("  %-8s to process 0: %s of %s tiles in %s messages, %s bytes (%s a tile); gathering them took "
                  "%s s (%.1f us a message)" % (name, tiles, total, msgs, nbytes, per, gather,
                                                1e6 * float(gather) / max(1, int(msgs))))
    print("  start-up, a 1-pixel render: plain %.3f s, under mpirun -np %d %.3f s (medians of %d)"
          % (statistics.median(start_plain), DIST_PROCESSES, statistics.median(start_mpi), len(start_plain)))


def main():
    ap = argparse.ArgumentParser(prog="bench/run", description="scn's benchmarks")
    ap.add_argument("--quick", action="store_true", help="one run of each, not three")
    ap.add_argument("--runs", type=int, help="runs of each measurement (default 3, --quick 1)")
    ap.add_argument("--full", action="store_true", help="also scn converge examples/whitted.scn (5 minutes)")
    ap.add_argument("--only", choices=["table", "language", "textures", "converge", "scaling", "embree", "processes"],
                    action="append",
                    help="run only these parts (repeatable); default: table, language, textures, scaling, "
                         "embree and processes (MPI, where mpirun and scn-mpi are), and converge with --full")
    ap.add_argument("--scene", action="append", metavar="NAME",
                    help="the table's scenes to run, by the name in its first column (repeatable: "
                         "--scene 'quadrics 1e4' --scene 'csg wall'), and converge's ('whitted', 'soft shadows'); "
                         "default every one")
    ap.add_argument("--work", default=os.environ.get("SCN_BENCH_DIR", "/tmp/scn-bench"),
                    help="where scenes, meshes and images go (default /tmp/scn-bench)")
    ap.add_argument("--svg", default=os.path.join(HERE, "scaling.svg"), help="the scaling plot's file")
    a = ap.parse_args()
    runs = a.runs or (1 if a.quick else 3)
    parts = a.only or ["table", "language", "textures", "scaling", "embree", "processes"] + (["converge"] if a.full else [])
    os.makedirs(a.work, exist_ok=True)
    subprocess.run(["make", "-s", "-C", TOP, "all"], check=True, stdout=subprocess.DEVNULL)
    with open("/proc/loadavg") as f:
        print("load average at the start: " + " ".join(f.read().split()[:3]) + "; %d cores" % os.cpu_count())
    t0 = time.time()
    if "table" in parts or "embree" in parts:
        table_scenes = make_scenes(a.work)
    if "table" in parts:
        if a.scene:
            unknown = set(a.scene) - {name for name, _, _ in table_scenes}
            if unknown:
                sys.exit("bench: no scene %s in the table" % ", ".join(sorted(unknown)))
        print_scene_table(scene_table(a.work, runs, table_scenes, a.scene), runs)
        print()
        sys.stdout.flush()
    if "language" in parts:
        print_language(*language(a.work, runs), runs)
        print()
        sys.stdout.flush()
    if "textures" in parts:
        print_textures(*textures(a.work, runs), runs)
        print()
        sys.stdout.flush()
    if "converge" in parts:
        converge(a.work, a.scene)
        print()
        sys.stdout.flush()
    if "embree" in parts:
        embree(a.work)
        print()
        sys.stdout.flush()
    if "processes" in parts:
        if shutil.which("mpirun") and os.path.exists(os.path.join(TOP, "scn-mpi")):
            print_distributed(*distributed(a.work, runs), runs)
        else:
            print("over processes: skipped, no mpirun or no scn-mpi (apt-get install openmpi-bin libopenmpi-dev, "
                  "then configure and make)")
        print()
        sys.stdout.flush()
    if "scaling" in parts:
        table = scaling(a.work, runs)
        print_scaling(table, runs)
        plot_scaling(table, a.svg)
        print("plot: " + os.path.relpath(a.svg))
    with open("/proc/loadavg") as f:
        print("load average at the end: %s; %.0f s in all" % (" ".join(f.read().split()[:3]), time.time() - t0))


if __name__ == "__main__":
    main()
