# Copyright (c) 2026 The CGAL Surface Design authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""QuadriFlow (Huang et al. 2018) as Blender ships it, run headless on one mesh.

usage: blender -b --factory-startup --python quadriflow_blender.py -- IN.obj OUT.obj TARGET_FACES

Imports IN.obj, runs bpy.ops.object.quadriflow_remesh(target_faces=TARGET_FACES) with the
boundary kept and no symmetry, and exports the result to OUT.obj with the same axes as the
input (import and export convert the same way, so the coordinates come back unchanged). Prints
one line "quadriflow: seconds S faces F" (S: the operator alone) or "quadriflow: failed ..." and
exits 1 (QuadriFlow refuses meshes it does not consider manifold and consistently oriented).
Called by quad_peer_comparison.py; the library never calls it.
"""
import sys
import time

import bpy


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(argv) != 3:
        print(__doc__)
        return 1
    source, target_path, target_faces = argv[0], argv[1], int(argv[2])
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.wm.obj_import(filepath=source)
    objects = [o for o in bpy.context.scene.objects if o.type == "MESH"]
    if len(objects) != 1:
        print("quadriflow: failed: %d mesh objects after the import" % len(objects))
        return 1
    mesh = objects[0]
    bpy.context.view_layer.objects.active = mesh
    mesh.select_set(True)
    faces_before = len(mesh.data.polygons)
    start = time.perf_counter()
    try:
        result = bpy.ops.object.quadriflow_remesh(target_faces=target_faces, use_mesh_symmetry=False,
                                                  use_preserve_sharp=False, use_preserve_boundary=True,
                                                  preserve_paint_mask=False, smooth_normals=False, mode="FACES",
                                                  seed=0)
    except RuntimeError as e:
        print("quadriflow: failed: " + str(e).replace("\n", " "))
        return 1
    seconds = time.perf_counter() - start
    faces = len(mesh.data.polygons)
    if "FINISHED" not in result or (faces == faces_before and all(len(p.vertices) == 3 for p in mesh.data.polygons)):
        print("quadriflow: failed: the operator returned %s and left the mesh as it was" % (result,))
        return 1
    bpy.ops.wm.obj_export(filepath=target_path, export_selected_objects=True, export_materials=False,
                          export_normals=False, export_uv=False, apply_modifiers=False)
    print("quadriflow: seconds %.6f faces %d" % (seconds, faces))
    return 0


if __name__ == "__main__":
    code = main()
    sys.stdout.flush()
    sys.exit(code)
