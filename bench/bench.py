"""bench.py: scn's benchmarks, run by bench/run (see it for the options).

The scene table: scn and POV-Ray 3.7 on the same scenes, runs alternating scn/POV-Ray, the
median of each; POV-Ray renders the scene `scn pov` writes, with the command line written at
its top plus +WT2. The scaling study: render time against the number of spheres for each
accelerator. The Embree table: bench/embree_compare. Scenes and meshes are generated into a
work folder (default /tmp/scn-bench), never committed."""

import argparse
import math
import os
import re
import shlex
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
STATS_RAYS = re.compile(r"^rays: +camera (\d+) +shadow (\d+) +reflection (\d+) +refraction (\d+) +total (\d+)$", re.M)


def scn_stats(text):
    """load, build, render and write seconds and the rays by kind from --stats."""
    t, r = STATS_TIME.search(text), STATS_RAYS.search(text)
    if not t or not r:
        sys.exit("bench: no --stats in scn's output:\n" + text[-2000:])
    t = [float(x) for x in t.groups()]
    rays = dict(zip(["camera", "shadow", "reflection", "refraction", "total"], (int(x) for x in r.groups())))
    return {"load": t[0] + t[1] + t[2] + t[3] + t[4], "build": t[5], "render": t[6], "write": t[7], "rays": rays}


def scn_render(scene, out, accel="bvh"):
    wall, mb, err = timed([SCN, "render", scene, "-o", out, "-j", str(THREADS), "--accel", accel, "--stats",
                           "--no-progress"])
    return {"wall": wall, "mb": mb, **scn_stats(err)}


def pov_command(pov, spp):
    """The povray command line at the top of a .pov that scn pov wrote, with +WT2, its
    anti-aliasing set to trace as many camera rays a pixel as scn's spp do."""
    with open(pov) as f:
        for line in f:
            if line.startswith("// Render: "):
                cmd = shlex.split(line[len("// Render: "):]) + ["+WT%d" % THREADS]
                return equal_rays_aa(cmd, int(spp))
    sys.exit("bench: %s has no '// Render:' line" % pov)


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


def pov_camera_rays(text):
    """POV-Ray's camera rays from its statistics: its pixels and its anti-aliasing samples."""
    m = POV_STATS.search(text)
    return int(m.group(1)) + int(m.group(2)) if m else float("nan")


def median_run(runs):
    """The run whose wall time is the median (the lower middle for an even count)."""
    ordered = sorted(runs, key=lambda r: r["wall"])
    return ordered[(len(ordered) - 1) // 2]


# ---- the scene table ----

def make_scenes(work):
    """[(name, description, scene path)]: the five scenes of the issue, and the solids of
    LANGUAGE.md section 9: 10^4 quadrics and tori, and a wall of 1000 CSG bricks."""
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
    return [("headline", "1000 spheres, mirror+glass, 2 lights", "headline.scn"),
            ("spheres 1e5", "100000 spheres, 1 light", "spheres-1e5.scn"),
            ("spheres 1e6", "1000000 spheres, 1 light", "spheres-1e6.scn"),
            ("bunny", "examples/bunny.ply, 3674 triangles", "bunny.scn"),
            ("bunny 1M", "bunny, midpoint-subdivided x4: 940544 triangles", "bunny-1m.scn"),
            ("quadrics 1e4", "10000 boxes, cylinders, cones, ellipsoids, tori (2000 each), 1 light", "quadrics-1e4.scn"),
            ("csg wall", "1000 bricks, each a difference of a box and a cylinder, 1 light", "csg-wall.scn")]


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
        s_runs, p_runs = [], []
        for i in range(runs):
            log("bench: %s: run %d of %d: scn, then POV-Ray" % (name, i + 1, runs))
            s_runs.append(scn_render(scene, os.path.join(work, file[:-4] + "-scn.png")))
            wall, mb, err = timed(cmd, cwd=work)
            p_runs.append({"wall": wall, "mb": mb, "camera": pov_camera_rays(err)})
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
    head = "%-12s %9s %9s %11s %11s %9s" % ("scene", "camera", "shadow", "reflection", "refraction", "total")
    print(head)
    print("-" * len(head))
    for name, _, _, s, _, _, _, _ in rows:
        r = s["rays"]
        rate = lambda k: "%.2f" % (r[k] / s["render"] * 1e-6) if r[k] else "-"
        print("%-12s %9s %9s %11s %11s %9s" % (name, rate("camera"), rate("shadow"), rate("reflection"),
                                               rate("refraction"), rate("total")))
    print()
    print("scenes:")
    for name, what, _, _, _, _, _, cmd in rows:
        print("  %-12s %s" % (name, what))
    print("POV-Ray's command for %s: " % rows[0][0] + " ".join(rows[0][7]))


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


def converge():
    log("bench: scn converge examples/whitted.scn --budget 300 (about 5 minutes)")
    p = subprocess.run([SCN, "converge", os.path.join(TOP, "examples", "whitted.scn"), "--budget", "300"],
                       capture_output=True, text=True, check=True)
    last = p.stdout.strip().splitlines()[-1]
    print("scn converge examples/whitted.scn --budget 300, its last line: " + last)


def main():
    ap = argparse.ArgumentParser(prog="bench/run", description="scn's benchmarks")
    ap.add_argument("--quick", action="store_true", help="one run of each, not three")
    ap.add_argument("--runs", type=int, help="runs of each measurement (default 3, --quick 1)")
    ap.add_argument("--full", action="store_true", help="also scn converge examples/whitted.scn (5 minutes)")
    ap.add_argument("--only", choices=["table", "converge", "scaling", "embree"], action="append",
                    help="run only these parts (repeatable); default: table, scaling and embree, and converge "
                         "with --full")
    ap.add_argument("--scene", action="append", metavar="NAME",
                    help="the table's scenes to run, by the name in its first column (repeatable: "
                         "--scene 'quadrics 1e4' --scene 'csg wall'); default every one")
    ap.add_argument("--work", default=os.environ.get("SCN_BENCH_DIR", "/tmp/scn-bench"),
                    help="where scenes, meshes and images go (default /tmp/scn-bench)")
    ap.add_argument("--svg", default=os.path.join(HERE, "scaling.svg"), help="the scaling plot's file")
    a = ap.parse_args()
    runs = a.runs or (1 if a.quick else 3)
    parts = a.only or ["table", "scaling", "embree"] + (["converge"] if a.full else [])
    os.makedirs(a.work, exist_ok=True)
    subprocess.run(["make", "-s", "-C", TOP, "scn"], check=True, stdout=subprocess.DEVNULL)
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
    if "converge" in parts:
        converge()
        print()
        sys.stdout.flush()
    if "embree" in parts:
        embree(a.work)
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
