#!/usr/bin/env python3
# Copyright (c) 2026 The CGAL Surface Design authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Side by side: stripes on the smoothest line field, ours against geometry-central's.

usage: stripe_peer_comparison.py BUILD_DIR GEOMETRY_CENTRAL_DIR [--mesh FILE.off]... [--runs R]
                                 [--json OUT.json] [--warm-heap]

Ours: BUILD_DIR/benchmark/surface_design_benchmark --workload line_field_stripes (the default
solver): the smoothest line field, then the stripes along it at 40 stripes across the bounding-box
diagonal, windings automatic, no singularity prescribed ("full" = "field" + "stripes"), and the
automatic stripe singularities on top ("automatic").
The peer: geometry-central's computeSmoothestVertexDirectionField(n = 2) and computeStripePattern
(Knöppel et al. 2015: its singularities are the ones its eigenvector has), the same frequency,
timed by peers/geometry_central_stripes.cpp. GEOMETRY_CENTRAL_DIR is a source checkout of
geometry-central (github.com/nmwsharp/geometry-central, with its deps/happly submodule) configured
and built in GEOMETRY_CENTRAL_DIR/build (`cmake -B build -DCMAKE_BUILD_TYPE=Release && make -C
build geometry-central`; with Debian's libsuitesparse-dev it uses CHOLMOD). The script compiles
the driver against it with -O3 (once; kept in BUILD_DIR/benchmark/geometry_central_stripes).
Both programs run one after the other on an otherwise idle machine, R runs each after a warm-up
(default 5), medians reported.

--warm-heap runs both programs with glibc's allocator told to keep freed memory (GLIBC_TUNABLES:
glibc.malloc.mmap_threshold at 32 MB, the largest it takes, and trim_threshold at 1 GB), so that
a run after the warm-up reuses pages already mapped instead of faulting in fresh ones: repeated
use. Without it, glibc gives large freed blocks back to the kernel, and a run pays the kernel's
zeroing of its fresh pages (about 12 us per 4 kB page on the development VM; 11 000 pages per
line_field_stripes call on bunny_60k). A long-running program such as the editor's server mostly
reuses its pages either way (glibc raises its thresholds to the blocks it has seen freed).
"""
import json
import os
import shlex
import subprocess
import sys
import tempfile

WARM_HEAP = "glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=1073741824"

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_MESHES = ["data/bunny_8k.off", "data/kitten.off", "../shared/data/meshes/bunny_60k.off",
                  "../shared/data/meshes/bunny_loop1_239k.off"]


def fail(message):
    print("stripe_peer_comparison.py: " + message, file=sys.stderr)
    sys.exit(1)


def build_driver(build_dir, gc_dir):
    driver = os.path.join(build_dir, "benchmark", "geometry_central_stripes")
    source = os.path.join(HERE, "peers", "geometry_central_stripes.cpp")
    if os.path.exists(driver) and os.path.getmtime(driver) >= os.path.getmtime(source):
        return driver
    library = os.path.join(gc_dir, "build", "src", "libgeometry-central.a")
    if not os.path.exists(library):
        fail(library + " not found: build geometry-central first (see --help)")
    flags = os.path.join(gc_dir, "build", "src", "CMakeFiles", "geometry-central.dir", "flags.make")
    defines = []
    with open(flags) as f:
        for line in f:
            if line.startswith("CXX_DEFINES"):
                defines = shlex.split(line.split("=", 1)[1])
    libs = ["-lpthread"]
    if "-DGC_HAVE_SUITESPARSE" in defines:
        libs = ["-lcholmod", "-lspqr", "-lumfpack", "-lamd", "-lcolamd", "-lcamd", "-lccolamd", "-lsuitesparseconfig",
                "-lmetis", "-lblas", "-llapack"] + libs
    command = (["c++", "-std=c++17", "-O3", "-DNDEBUG"] + defines +
               ["-I" + os.path.join(gc_dir, "include"), "-I" + os.path.join(gc_dir, "deps", "happly"),
                "-I" + os.path.join(gc_dir, "deps", "nanoflann", "include"), "-isystem", "/usr/include/eigen3",
                "-isystem", "/usr/include/suitesparse", source, library, "-o", driver] + libs)
    print("building the peer's driver: " + " ".join(command), flush=True)
    if subprocess.run(command).returncode != 0:
        fail("could not build " + source)
    return driver


def ours(build_dir, mesh, runs):
    program = os.path.join(build_dir, "benchmark", "surface_design_benchmark")
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "ours.json")
        result = subprocess.run([program, "--workload", "line_field_stripes", "--mesh", mesh_source(mesh), "--solver",
                                 "default", "--runs", str(runs), "--json", out], capture_output=True, text=True)
        if result.returncode != 0 or not os.path.exists(out):
            fail("our benchmark failed on " + mesh + ":\n" + result.stdout + result.stderr)
        with open(out) as f:
            data = json.load(f)
    phases = {r["phase"]: r for r in data["results"] if r["workload"] == "line_field_stripes"}
    if "full" not in phases:
        fail("our benchmark reported no result on " + mesh + ":\n" + result.stdout)
    return phases, data["machine"]


def mesh_source(path):
    """The benchmark's name of a mesh file: bundled: (data/) or shared: (the shared mesh folder)."""
    absolute = os.path.abspath(path)
    data = os.path.abspath(os.path.join(HERE, "..", "data"))
    if os.path.dirname(absolute) == data:
        return "bundled:" + os.path.basename(absolute)
    os.environ["CGAL_SURFACE_DESIGN_SHARED_MESH_DIR"] = os.path.dirname(absolute)
    return "shared:" + os.path.basename(absolute)


def peer(driver, mesh, runs):
    result = subprocess.run([driver, mesh, str(runs)], capture_output=True, text=True)
    if result.returncode != 0:
        fail("geometry-central failed on " + mesh + ":\n" + result.stdout + result.stderr)
    return json.loads(result.stdout.strip().splitlines()[-1])


def main(argv):
    if len(argv) < 2 or argv[0] in ("-h", "--help"):
        print(__doc__)
        return 0 if argv and argv[0] in ("-h", "--help") else 1
    build_dir, gc_dir = os.path.abspath(argv[0]), os.path.abspath(argv[1])
    meshes, runs, json_out, warm_heap = [], 5, None, False
    k = 2
    while k < len(argv):
        if argv[k] == "--warm-heap":
            warm_heap = True
            k += 1
        elif argv[k] in ("--mesh", "--runs", "--json") and k + 1 < len(argv):
            if argv[k] == "--mesh":
                meshes.append(argv[k + 1])
            elif argv[k] == "--runs":
                try:
                    runs = int(argv[k + 1])
                except ValueError:
                    fail("--runs: not an integer: " + argv[k + 1])
                if runs < 1:
                    fail("--runs must be at least 1")
            else:
                json_out = argv[k + 1]
            k += 2
        else:
            fail("unknown or incomplete option: " + argv[k])
    if not meshes:
        root = os.path.join(HERE, "..")
        meshes = [os.path.join(root, m) for m in DEFAULT_MESHES]
    for m in meshes:
        if not os.path.exists(m):
            fail("mesh not found: " + m)
    if not os.path.isdir(gc_dir):
        fail("not a geometry-central checkout: " + gc_dir)
    if not os.path.exists(os.path.join(build_dir, "benchmark", "surface_design_benchmark")):
        fail("no benchmark in " + build_dir + " (build the target surface_design_benchmark)")
    driver = build_driver(build_dir, gc_dir)
    if warm_heap:
        # both children inherit it
        os.environ["GLIBC_TUNABLES"] = WARM_HEAP
    else:
        os.environ.pop("GLIBC_TUNABLES", None)
    rows, machine = [], None
    for m in meshes:
        print("mesh " + m + ": ours ...", flush=True)
        mine, machine = ours(build_dir, m, runs)
        print("  geometry-central ...", flush=True)
        theirs = peer(driver, m, runs)
        rows.append({"mesh": os.path.basename(m), "faces": theirs["faces"],
                     "ours": {p: mine[p]["median_ms"] for p in ("field", "stripes", "full", "automatic", "edit")},
                     "geometry_central": {p: theirs[p]["median_ms"] for p in ("field", "stripes", "full")},
                     "geometry_central_singular_faces": theirs["stripe_singular_faces"],
                     "speedup_full": theirs["full"]["median_ms"] / mine["full"]["median_ms"],
                     "speedup_field": theirs["field"]["median_ms"] / mine["field"]["median_ms"],
                     "speedup_full_plus_automatic": theirs["full"]["median_ms"] /
                     (mine["full"]["median_ms"] + mine["automatic"]["median_ms"])})
    print("\nmedians of %d runs, milliseconds; speed-up = geometry-central / ours; %s" %
          (runs, "warm heap (GLIBC_TUNABLES=" + WARM_HEAP + ")" if warm_heap else "glibc's default allocator"))
    print("| mesh | faces | ours: field | stripes | full | automatic | gc: field | stripes | full | "
          "speed-up full | field | full + automatic |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        o, g = r["ours"], r["geometry_central"]
        print("| %s | %d | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1fx | %.1fx | %.1fx |" %
              (r["mesh"], r["faces"], o["field"], o["stripes"], o["full"], o["automatic"], g["field"], g["stripes"],
               g["full"], r["speedup_full"], r["speedup_field"], r["speedup_full_plus_automatic"]))
    if json_out:
        with open(json_out, "w") as f:
            json.dump({"machine": machine, "runs": runs, "warm_heap": warm_heap, "results": rows}, f, indent=2)
        print("results written to " + json_out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
