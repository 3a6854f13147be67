#!/usr/bin/env python3
# Copyright (c) 2026 The CGAL Surface Design authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Side by side: quad_remesh (ours), gmsh's quad recombination and QuadriFlow on the same meshes.

usage: quad_peer_comparison.py BUILD_DIR [--mesh FILE.off[:FACES]]... [--runs R] [--json OUT.json]
                               [--peers gmsh,quadriflow] [--methods harmonic,field,auto]

Every mesh is remeshed at one target, FACES faces (default 3000), by all: ours with
`quad_remesh --method M --target-faces FACES` for each method M, QuadriFlow with target_faces =
FACES, gmsh with the size h = sqrt(area / FACES).

Every peer runs when it is installed, else the script says so and goes on without it: gmsh
(Debian package `gmsh`) and QuadriFlow (Huang et al. 2018) inside Blender (Debian package
`blender`, run headless: `blender -b --factory-startup --python quadriflow_blender.py`). All
outputs are measured by BUILD_DIR/benchmark/quad_mesh_report (the library's quad_mesh_quality():
the same code for all).
- gmsh: STL input, ClassifySurfaces (the angle tried at 40, 20, 30, 50, 60, 70, 80 degrees until a
  mesh comes out), CreateGeometry, Frontal-Delaunay (Mesh.Algorithm 6) and Blossom recombination,
  uniform size h = sqrt(area / FACES), with the size-from-points and extend-from-boundary options
  off.
- QuadriFlow: OBJ input, `bpy.ops.object.quadriflow_remesh` with target_faces = FACES, the
  boundary kept, no symmetry, seed 0.
Times are medians of R runs (default 3) of the whole program, reading and writing included
("program s"; ours also certifies its Hausdorff distance there; Blender's start-up is in it),
and the remeshing alone ("remeshing s": ours from its own report, QuadriFlow the operator's time
measured inside Blender, gmsh the same as the program).
"""
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ANGLES = (40, 20, 30, 50, 60, 70, 80) # degrees for ClassifySurfaces, tried in this order
DEFAULT_MESHES = ["eight.off", "kitten.off", "fertility.off", "hemisphere.off", "camelhead.off", "torus.off", "bunny_8k.off",
                  "spot_2k.off"]


def read_off(path):
    words = []
    with open(path) as f:
        for line in f:
            line = line.split("#")[0]
            words.extend(line.split())
    if not words or words[0] != "OFF":
        raise ValueError(path + ": not an OFF file")
    nv, nf = int(words[1]), int(words[2])
    pos = 4
    points = [tuple(float(x) for x in words[pos + 3 * k: pos + 3 * k + 3]) for k in range(nv)]
    pos += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(words[pos])
        faces.append([int(x) for x in words[pos + 1: pos + 1 + n]])
        pos += 1 + n
    return points, faces


def write_stl(points, faces, path):
    with open(path, "w") as f:
        f.write("solid input\n")
        for t in faces:
            a, b, c = (points[i] for i in t[:3])
            u = [b[i] - a[i] for i in range(3)]
            v = [c[i] - a[i] for i in range(3)]
            n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
            f.write("facet normal %r %r %r\nouter loop\n" % tuple(n))
            for p in (a, b, c):
                f.write("vertex %r %r %r\n" % p)
            f.write("endloop\nendfacet\n")
        f.write("endsolid input\n")


def area(points, faces):
    total = 0.
    for t in faces:
        a, b, c = (points[i] for i in t[:3])
        u = [b[i] - a[i] for i in range(3)]
        v = [c[i] - a[i] for i in range(3)]
        n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        total += 0.5 * math.sqrt(sum(x * x for x in n))
    return total


def vtk_to_off(vtk, off):
    """gmsh's legacy VTK (ASCII): the triangles (type 5) and quads (type 9) as an OFF file."""
    words = open(vtk).read().split()
    i = words.index("POINTS")
    nv = int(words[i + 1])
    pts = words[i + 3: i + 3 + 3 * nv]
    i = words.index("CELLS")
    nc = int(words[i + 1])
    pos = i + 3
    cells = []
    for _ in range(nc):
        n = int(words[pos])
        cells.append([int(x) for x in words[pos + 1: pos + 1 + n]])
        pos += 1 + n
    i = words.index("CELL_TYPES")
    types = [int(x) for x in words[i + 2: i + 2 + nc]]
    polys = [c for c, t in zip(cells, types) if t in (5, 9)]
    with open(off, "w") as f:
        f.write("OFF\n%d %d 0\n" % (nv, len(polys)))
        for k in range(nv):
            f.write(" ".join(pts[3 * k: 3 * k + 3]) + "\n")
        for c in polys:
            f.write("%d %s\n" % (len(c), " ".join(map(str, c))))


def timed(command, runs):
    """(median seconds, the last run's result, every run's stdout)"""
    times, outputs, result = [], [], None
    for _ in range(runs):
        start = time.perf_counter()
        result = subprocess.run(command, capture_output=True, text=True)
        times.append(time.perf_counter() - start)
        outputs.append(result.stdout)
        if result.returncode != 0:
            break
    return statistics.median(times), result, outputs


def report(build, reference, polygons):
    r = subprocess.run([os.path.join(build, "benchmark", "quad_mesh_report"), reference, polygons],
                       capture_output=True, text=True)
    return json.loads(r.stdout) if r.returncode == 0 else {"error": r.stderr.strip()}


def run_gmsh(stl, out_vtk, h, angle, runs):
    geo = out_vtk + ".geo"
    with open(geo, "w") as f:
        f.write('Merge "%s";\n' % stl)
        f.write("ClassifySurfaces{%r * Pi / 180, 1, 1, Pi};\nCreateGeometry;\n" % float(angle))
        f.write("Mesh.Algorithm = 6;\nMesh.RecombineAll = 1;\nMesh.RecombinationAlgorithm = 1;\n")
        f.write("Mesh.MeshSizeMin = %r;\nMesh.MeshSizeMax = %r;\n" % (h, h))
        f.write("Mesh.MeshSizeFromPoints = 0;\nMesh.MeshSizeExtendFromBoundary = 0;\n")
        f.write("Mesh.MeshSizeFromCurvature = 0;\n")
    if os.path.exists(out_vtk):
        os.remove(out_vtk)
    seconds, result, _ = timed(["gmsh", geo, "-2", "-format", "vtk", "-o", out_vtk], runs)
    ok = result.returncode == 0 and os.path.exists(out_vtk)
    return ok, seconds, result.stderr + result.stdout


def write_obj(points, faces, path):
    with open(path, "w") as f:
        for p in points:
            f.write("v %r %r %r\n" % p)
        for t in faces:
            f.write("f " + " ".join(str(i + 1) for i in t) + "\n")


def run_quadriflow(obj, out_obj, target_faces, runs):
    """QuadriFlow inside Blender: (ok, program seconds, operator seconds, log)."""
    script = os.path.join(HERE, "quadriflow_blender.py")
    operator = []
    seconds, result = None, None
    times = []
    for _ in range(runs):
        if os.path.exists(out_obj):
            os.remove(out_obj)
        start = time.perf_counter()
        result = subprocess.run(["blender", "-b", "--factory-startup", "--python", script, "--", obj, out_obj,
                                 str(target_faces)], capture_output=True, text=True)
        times.append(time.perf_counter() - start)
        found = re.search(r"quadriflow: seconds ([\d.]+) faces (\d+)", result.stdout)
        if result.returncode != 0 or not found or not os.path.exists(out_obj):
            failed = re.search(r"quadriflow: failed.*", result.stdout)
            return False, None, None, failed.group(0) if failed else (result.stderr.strip().splitlines() or ["failed"])[-1]
        operator.append(float(found.group(1)))
    seconds = statistics.median(times)
    return True, seconds, statistics.median(operator), ""


def main(argv):
    if len(argv) < 2 or argv[1].startswith("-"):
        print(__doc__)
        return 1
    build = argv[1]
    meshes, runs, out_json = [], 3, "quad_peer_comparison.json"
    peers = ["gmsh", "quadriflow"]
    methods = ["harmonic", "field"]
    k = 2
    while k < len(argv):
        if argv[k] == "--mesh" and k + 1 < len(argv):
            meshes.append(argv[k + 1])
        elif argv[k] == "--peers" and k + 1 < len(argv):
            peers = [p for p in argv[k + 1].split(",") if p]
            if any(p not in ("gmsh", "quadriflow") for p in peers):
                print("quad_peer_comparison.py: --peers takes gmsh and/or quadriflow")
                return 1
        elif argv[k] == "--methods" and k + 1 < len(argv):
            methods = [m for m in argv[k + 1].split(",") if m]
            if not methods or any(m not in ("harmonic", "field", "auto") for m in methods):
                print("quad_peer_comparison.py: --methods takes harmonic, field and/or auto")
                return 1
        elif argv[k] == "--runs" and k + 1 < len(argv):
            runs = int(argv[k + 1])
        elif argv[k] == "--json" and k + 1 < len(argv):
            out_json = argv[k + 1]
        else:
            print("quad_peer_comparison.py: unknown option " + argv[k])
            return 1
        k += 2
    if not meshes:
        meshes = [os.path.join(HERE, "..", "data", m) for m in DEFAULT_MESHES]
    if "gmsh" in peers and shutil.which("gmsh") is None:
        print("gmsh is not installed (Debian: apt-get install gmsh): it is left out")
        peers.remove("gmsh")
    if "quadriflow" in peers and shutil.which("blender") is None:
        print("Blender is not installed (Debian: apt-get install blender): QuadriFlow is left out")
        peers.remove("quadriflow")
    quad_remesh = os.path.join(build, "examples", "quad_remesh")
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for spec in meshes:
            mesh, _, wanted = spec.partition(":")
            target = int(wanted) if wanted else 3000
            name = os.path.splitext(os.path.basename(mesh))[0]
            points, faces = read_off(mesh)
            h = math.sqrt(area(points, faces) / target)
            print("== %s (%d faces), %d faces wanted, h = %.4g" % (name, len(faces), target, h), flush=True)
            row = {"mesh": name, "input_faces": len(faces), "target_faces": target, "h": h}
            for method in methods:
                ours_off = os.path.join(work, name + "_" + method + ".off")
                seconds, result, outputs = timed([quad_remesh, mesh, "--method", method, "--target-faces",
                                                  str(target), "--output", ours_off], runs)
                ours = report(build, mesh, ours_off) if result.returncode == 0 else {
                    "error": (result.stderr.strip().splitlines() or ["failed"])[-1]}
                ours["seconds"] = seconds
                # the remeshing alone (the program also certifies its Hausdorff distance): its own
                # times (summed over the components, which the field method remeshes one by one),
                # the median over the runs
                remesh = []
                for output in outputs:
                    total = None
                    for line in output.splitlines():
                        # the four phases (quads only and snapping, in brackets, are part of meshing)
                        phases = re.match(r"times: harmonic ([\d.]+) s, spectacles \(re-solve\) ([\d.]+) s, "
                                          r"curves ([\d.]+) s, meshing ([\d.]+) s", line)
                        if not phases:
                            phases = re.match(r"times: field ([\d.]+) s, stripes ([\d.]+) s, extraction ([\d.]+) s",
                                              line)
                        if phases:
                            total = (total or 0.) + sum(float(x) for x in phases.groups())
                    if total is not None:
                        remesh.append(total)
                # (auto: not its failed field attempts before a harmonic fall-back, which print no
                # times; the program's time holds them)
                if remesh and method != "auto":
                    ours["remesh_seconds"] = statistics.median(remesh)
                # auto: the method it used ("field", "harmonic", "field on 1 of 3 components, ...")
                used = [l[len("method: "):].split(" (auto")[0] for l in (outputs[0] if outputs else "").splitlines()
                        if l.startswith("method: ")]
                if used:
                    ours["method_used"] = used[0]
                row["ours " + method] = ours
            if "quadriflow" in peers:
                obj = os.path.join(work, name + ".obj")
                write_obj(points, faces, obj)
                out_obj = os.path.join(work, name + "_quadriflow.obj")
                ok, seconds, operator, log = run_quadriflow(obj, out_obj, target, runs)
                if ok:
                    row["quadriflow"] = report(build, mesh, out_obj)
                    row["quadriflow"].update({"seconds": seconds, "remesh_seconds": operator, "target_faces": target})
                else:
                    row["quadriflow"] = {"error": "refused or failed: " + log}
            whos = ["ours " + m for m in methods] + ["gmsh", "quadriflow"]
            if "gmsh" not in peers:
                rows.append(row)
                for who in whos:
                    if who in row:
                        print("  %-13s %s" % (who, json.dumps(row[who])), flush=True)
                continue
            stl = os.path.join(work, name + ".stl")
            write_stl(points, faces, stl)
            vtk = os.path.join(work, name + "_gmsh.vtk")
            gmsh = {"error": "no angle worked"}
            for angle in ANGLES:
                ok, seconds, log = run_gmsh(stl, vtk, h, angle, runs)
                if ok:
                    gmsh_off = os.path.join(work, name + "_gmsh.off")
                    vtk_to_off(vtk, gmsh_off)
                    gmsh = report(build, mesh, gmsh_off)
                    gmsh["seconds"] = seconds
                    gmsh["classify_angle"] = angle
                    break
                errors = [l for l in log.splitlines() if "Error" in l]
                gmsh = {"error": "no mesh with any of the angles %s; last: %s" % (
                    ", ".join(map(str, ANGLES)), errors[-1].strip() if errors else "failed")}
            row["gmsh"] = gmsh
            rows.append(row)
            for who in whos:
                if who in row:
                    print("  %-13s %s" % (who, json.dumps(row[who])), flush=True)
    with open(out_json, "w") as f:
        json.dump(rows, f, indent=1)
    keys = [("faces", "faces", "%d"), ("quads %", "quad_fraction", "%.1f"), ("irregular / face", None, "%.3f"),
            ("|angle-90| mean", "angle_deviation_mean", "%.1f"), ("Hausdorff %", "relative_hausdorff_distance", "%.2f"),
            ("valid, topology", None, "%s"), ("flipped faces", "reoriented_faces", "%d"), ("program s", "seconds", "%.3f"),
            ("remeshing s", "remesh_seconds", "%.3f")]
    print("\n| mesh | who | " + " | ".join(k[0] for k in keys) + " |")
    print("|---|---|" + "---:|" * len(keys))
    for row in rows:
        for who in ["ours " + m for m in methods] + ["gmsh", "quadriflow"]:
            if who not in row:
                continue
            r = row[who]
            if "error" in r:
                print("| %s | %s | %s |" % (row["mesh"], who, r["error"]))
                continue
            cells = []
            for label, key, fmt in keys:
                if label == "irregular / face":
                    cells.append(fmt % (r["irregular_vertices"] / max(r["faces"], 1)))
                elif label == "valid, topology":
                    cells.append("%s, %s" % ("valid" if r["valid"] else "invalid", "kept" if r["same_topology"] else "changed"))
                elif key == "remesh_seconds":
                    cells.append(fmt % r.get(key, r["seconds"]))
                elif key in ("quad_fraction", "relative_hausdorff_distance"):
                    cells.append(fmt % (100. * r[key]))
                else:
                    cells.append(fmt % r[key])
            label = who + (" (%s)" % r["method_used"] if "method_used" in r else "")
            print("| %s | %s | %s |" % (row["mesh"], label, " | ".join(cells)))
    print("\nresults written to " + out_json)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
