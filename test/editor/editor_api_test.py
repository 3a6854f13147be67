# Copyright (c) 2026 The CGAL Surface Design authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Tests of the stripe editor's HTTP API: starts surface_design_editor on a free loopback port,
edits singularities, fields and frequencies, and checks the results against an independent
reading of the stripes (the winding of the exported per-vertex alpha around every face must be
exactly the prescribed index; cos of the per-corner data must equal cos alpha at the corner's
vertex). Every invalid request must get a clear error and leave the state exactly as it was.

usage: editor_api_test.py EDITOR DATA_DIR"""

import json
import math
import os
import sys
import threading

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from editor_support import Server  # noqa: E402

passed = failed = 0


def check(name, ok, detail=""):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print(f"FAILED  {name}" + (f"  ({detail})" if detail else ""))


def read_ply(text):
    """(alpha per vertex, triangles, index per face) of the editor's ASCII PLY."""
    lines = text.splitlines()
    nv = nf = 0
    for line in lines:
        if line.startswith("element vertex"):
            nv = int(line.split()[2])
        elif line.startswith("element face"):
            nf = int(line.split()[2])
    start = lines.index("end_header") + 1
    alpha = [float(line.split()[3]) for line in lines[start:start + nv]]
    faces, index = [], []
    for line in lines[start + nv:start + nv + nf]:
        items = line.split()
        faces.append(tuple(int(x) for x in items[1:4]))
        index.append(int(items[4]))
    return alpha, faces, index


def wrap(x):
    return (x + math.pi) % (2 * math.pi) - math.pi


def windings(server):
    """Face -> winding of the exported alpha around it (non-zero ones), plus the PLY's data."""
    status, _, body = server.request("GET", "api/export.ply")
    assert status == 200
    alpha, faces, index = read_ply(body.decode())
    found = {}
    for f, (a, b, c) in enumerate(faces):
        turn = wrap(alpha[b] - alpha[a]) + wrap(alpha[c] - alpha[b]) + wrap(alpha[a] - alpha[c])
        k = round(turn / (2 * math.pi))
        if k != 0:
            found[f] = k
    return found, alpha, faces, index


def singularities(state, family=0):
    """Face -> index of one stripe family (the state lists [face, index, family])."""
    return {f: k for f, k, a in state["singularities"] if a == family}


def expect_refused(server, request, words, what):
    """The request gets a 4xx with a message containing all `words`, and the state is unchanged."""
    before = server.state()
    status, message, _ = server.edit(request)
    check(f"{what}: refused", 400 <= status < 500, f"status {status}")
    text = message if isinstance(message, str) else json.dumps(message)
    check(f"{what}: the message says why", all(w.lower() in text.lower() for w in words), text)
    after = server.state()
    # the whole state but the timings: singularities, field and its singularities, branch faces,
    # order, frequency, energy, version, and every float of the corner data and the overlay
    strip = lambda state: {k: v for k, v in state.items() if k != "timing"}
    same = strip(before[0]) == strip(after[0]) and before[1] == after[1]
    check(f"{what}: the state is unchanged", same)


def expect_blocked(server, status, words, what, method="POST", path="api/edit",
                   body='{"op": "add_pair", "plus": 10, "minus": 20}', **options):
    """A request refused before it reaches the session: the status, a message with all `words`,
    and the state left exactly as it was."""
    before = server.state()
    got, _, content = server.request(method, path, body if method == "POST" else None, **options)
    check(f"{what}: refused with {status}", got == status, f"status {got}")
    try:
        message = json.loads(content)["error"]
    except (ValueError, KeyError):
        message = content[:200]
    check(f"{what}: the message says why", all(w.lower() in str(message).lower() for w in words), message)
    after = server.state()
    check(f"{what}: the state is unchanged", before[0]["version"] == after[0]["version"] and before[1] == after[1] and
          before[0]["singularities"] == after[0]["singularities"])


def hostile_requests(server):
    """The editor as a page on another site, or a rebinding domain, would try to drive it."""
    port = server.host.split(":")[1]
    evil = {"Origin": "http://evil.example"}
    expect_blocked(server, 403, ["token"], "an edit without the token", token=False)
    expect_blocked(server, 403, ["token"], "an edit with a wrong token", headers={"X-Editor-Token": "0" * 32})
    expect_blocked(server, 403, ["token"], "a token one character short", headers={"X-Editor-Token": server.token[:-1]})
    expect_blocked(server, 403, ["token"], "the state without the token", method="GET", path="api/state", token=False)
    expect_blocked(server, 403, ["token"], "the PLY without the token", method="GET", path="api/export.ply", token=False)
    expect_blocked(server, 403, ["another site"], "an edit from another site's page (text/plain, as a form sends)",
                   content_type="text/plain", headers=evil, token=False)
    expect_blocked(server, 403, ["another site"], "an edit from another site's page, even with the token", headers=evil)
    expect_blocked(server, 403, ["another site"], "an edit from a sandboxed page (Origin null)", headers={"Origin": "null"})
    expect_blocked(server, 403, ["another site"], "an edit from https on the editor's own host",
                   headers={"Origin": "https://" + server.host})
    expect_blocked(server, 415, ["application/json"], "an edit sent as text/plain", content_type="text/plain")
    expect_blocked(server, 415, ["application/json"], "an edit sent as a form",
                   content_type="application/x-www-form-urlencoded")
    expect_blocked(server, 403, ["host", "evil.example"], "an edit through a rebinding domain",
                   headers={"Host": "evil.example:" + port})
    expect_blocked(server, 403, ["host"], "the state through a rebinding domain", method="GET", path="api/state",
                   headers={"Host": "evil.example:" + port})
    expect_blocked(server, 403, ["host"], "the page through a rebinding domain", method="GET", path="",
                   headers={"Host": "evil.example:" + port})
    expect_blocked(server, 403, ["host"], "the editor's host on another port", method="GET", path="api/state",
                   headers={"Host": "127.0.0.1:1"})
    # what the editor's own page and a user's tools do is accepted
    status, _, _ = server.request("GET", "", token=False)
    check("the page itself needs no token", status == 200, status)
    status, _, _ = server.request("GET", "api/state", headers={"Host": "localhost:" + port})
    check("the state under the name localhost", status == 200, status)
    status, _, body = server.request("GET", "api/export.ply?token=" + server.token, token=False)
    check("the PLY download link carries the token in its query", status == 200 and body.startswith(b"ply"), status)
    status, _, _ = server.request("POST", "api/edit", '{"op": "state"}', headers={"Origin": "http://" + server.host})
    check("an edit from the editor's own page", status == 200, status)
    status, _, _ = server.request("POST", "api/edit", '{"op": "state"}', content_type="application/json; charset=utf-8")
    check("application/json with a charset", status == 200, status)


def corner_readings(mesh, state, data):
    """An independent reading of a line or cross field's pattern from the state's corner data:
    (worst mismatch of the angle increments along the interior edges between two regular faces
    without singularity, up to the field's symmetry; face -> winding of the wrapped corner values
    of each family, where it is not 0, regular faces only)."""
    nf, families = state["faces"], state["families"]
    u = [data[0:3 * nf]] + ([data[3 * nf:6 * nf]] if families == 2 else [])
    T = mesh["triangles"]
    branch = {f for f, _ in state["branch_faces"]}
    singular = {f for f, _, _ in state["singularities"]}
    wound = {}
    for f in range(nf):
        if f in branch:
            continue
        for a in range(families):
            c = u[a][3 * f:3 * f + 3]
            k = round((wrap(c[1] - c[0]) + wrap(c[2] - c[1]) + wrap(c[0] - c[2])) / (2 * math.pi))
            if k:
                wound[(f, a)] = k
    edge_faces = {}
    for f in range(nf):
        for k in range(3):
            a, b = T[3 * f + k], T[3 * f + (k + 1) % 3]
            edge_faces.setdefault((min(a, b), max(a, b)), []).append((f, k))
    worst = 0.0
    for (a, b), pair in edge_faces.items():
        if len(pair) != 2 or any(f in branch or f in singular for f, _ in pair):
            continue
        steps = []
        for f, k in pair:  # the increment of each family from vertex a to vertex b in face f
            i, j = (k, (k + 1) % 3) if T[3 * f + k] == a else ((k + 1) % 3, k)
            steps.append([u[x][3 * f + j] - u[x][3 * f + i] for x in range(families)])
        x, y = steps
        maps = [[y[0]], [-y[0]]] if families == 1 else [[y[0], y[1]], [y[1], -y[0]], [-y[0], -y[1]], [-y[1], y[0]]]
        worst = max(worst, min(max(abs(p - q) for p, q in zip(x, m)) for m in maps))
    return worst, wound


def line_and_cross_fields(server):
    """Stripes on line (order 2) and cross (order 4) fields: the branch faces drawn as three
    triangles, stripe singularities of each family placed, moved and annihilated exactly, field
    singularities of +-1/2 placed, dragged and annihilated. On the 1k-face bunny (the factorizations
    of every field change run under the sanitizers too)."""
    status, state, _ = server.edit({"op": "load", "name": "bunny_1k.off"})
    check("line and cross fields: the 1k bunny loaded", status == 200, state)
    mesh = server.json("api/mesh")
    nf = mesh["faces"]
    P, T = mesh["positions"], mesh["triangles"]

    def smallest_angle(f):
        p = [P[3 * T[3 * f + k]:3 * T[3 * f + k] + 3] for k in range(3)]
        angles = []
        for k in range(3):
            u = [p[(k + 1) % 3][i] - p[k][i] for i in range(3)]
            v = [p[(k + 2) % 3][i] - p[k][i] for i in range(3)]
            dot = sum(x * y for x, y in zip(u, v))
            angles.append(math.acos(max(-1.0, min(1.0, dot / math.sqrt(sum(x * x for x in u) * sum(x * x for x in v))))))
        return min(angles)

    def free_faces(branch, count):
        """Well-shaped faces (every angle above 45 degrees: a vortex there spreads over its three
        edges, so the wrapped corner data shows it) sharing no vertex with a branch face, spread out."""
        near = {v for f in branch for v in T[3 * f:3 * f + 3]}
        good = [f for f in range(nf) if smallest_angle(f) > math.radians(45) and not (set(T[3 * f:3 * f + 3]) & near)]
        return [good[i * len(good) // count] for i in range(count)]

    # few stripes per edge, so that the wrapped corner data shows every singularity where it is
    status, state, _ = server.edit({"op": "frequency", "stripes": state["max_stripes"] / 5})
    check("line and cross fields: a low frequency", status == 200, state)
    status, state, data = server.edit({"op": "field", "kind": "smoothest", "order": 2})
    check("line field: order 2, one family", status == 200 and state["order"] == 2 and state["families"] == 1, state)
    branch = {f for f, _ in state["branch_faces"]}
    check("line field: the bunny's smoothest line field has branch faces of index +-1/2, summing to 2",
          len(branch) >= 4 and sum(k for _, k in state["branch_faces"]) == 4 and
          all(abs(k) % 2 == 1 for _, k in state["branch_faces"]), state["branch_faces"])
    check("line field: three triangles per branch face, 15 floats each, after the corner data",
          state["overlay"] == 3 * len(branch) and len(data) == 3 * nf + 15 * state["overlay"], (state["overlay"], len(data)))
    check("line field: the stripe singularities of the vector field are dropped", state["singularities"] == [])
    worst, wound = corner_readings(mesh, state, data)
    check("line field: the pattern is continuous across every regular edge (up to sign)", worst < 1e-3, worst)
    check("line field: no stripe singularity", wound == {}, wound)
    free = free_faces(branch, 4)
    status, state, data = server.edit({"op": "add_pair", "plus": free[0], "minus": free[1]})
    check("line field: a +1/-1 pair", status == 200 and singularities(state) == {free[0]: 1, free[1]: -1}, state)
    worst, wound = corner_readings(mesh, state, data)
    check("line field: the corner data winds exactly there", wound == {(free[0], 0): 1, (free[1], 0): -1}, wound)
    status, state, data = server.edit({"op": "move", "from": free[1], "to": free[2]})
    check("line field: move", status == 200 and singularities(state) == {free[0]: 1, free[2]: -1}, state)
    worst, wound = corner_readings(mesh, state, data)
    check("line field: after the move the corner data winds at the new face", wound == {(free[0], 0): 1, (free[2], 0): -1}, wound)
    check("line field: a move is a back-substitution (no factorization timed)", "factor_and_solve_ms" not in state["timing"],
          state["timing"])
    expect_refused(server, {"op": "add", "face": min(branch), "index": 1}, ["branch"], "a stripe singularity in a branch face")
    expect_refused(server, {"op": "add_pair", "plus": free[3], "minus": free[0], "family": 1}, ["one family"],
                   "the second family on a line field")
    status, state, data = server.edit({"op": "annihilate", "a": free[0], "b": free[2]})
    check("line field: annihilate", status == 200 and state["singularities"] == [], state)
    status, state, _ = server.edit({"op": "automatic"})
    check("line field: automatic singularities", status == 200 and "automatic_ms" in state["timing"], state)
    status, _, body = server.request("GET", "api/export.ply")
    check("line field: the PLY has the corner angles", status == 200 and b"property list uchar float corner_alpha" in body and
          b"stripe_index" in body and b"field_index" in body, body[:400])

    # a cross field: two families
    status, state, data = server.edit({"op": "field", "kind": "smoothest", "order": 4})
    check("cross field: order 4, two families", status == 200 and state["order"] == 4 and state["families"] == 2, state)
    branch = {f for f, _ in state["branch_faces"]}
    check("cross field: branch faces summing to 4 chi = 8 quarters", sum(k for _, k in state["branch_faces"]) == 8,
          state["branch_faces"])
    check("cross field: both families' corner data and the overlay",
          len(data) == 6 * nf + 15 * state["overlay"] and state["overlay"] == 3 * len(branch), len(data))
    free = free_faces(branch, 3)
    status, state, data = server.edit({"op": "add_pair", "plus": free[0], "minus": free[1], "family": 1})
    check("cross field: a pair of the second family", status == 200 and singularities(state, 1) == {free[0]: 1, free[1]: -1}
          and singularities(state, 0) == {}, state)
    worst, wound = corner_readings(mesh, state, data)
    check("cross field: continuous across regular edges up to quarter turns", worst < 1e-3, worst)
    check("cross field: the second family winds exactly there", wound == {(free[0], 1): 1, (free[1], 1): -1}, wound)
    status, state, data = server.edit({"op": "move", "from": free[1], "to": free[2]})
    check("cross field: move", status == 200 and singularities(state, 1) == {free[0]: 1, free[2]: -1}, state)
    expect_refused(server, {"op": "annihilate", "a": free[0], "b": free[0] + 1}, ["opposite"], "annihilating a lone singularity")
    status, state, data = server.edit({"op": "annihilate", "a": free[0], "b": free[2]})
    check("cross field: annihilate", status == 200 and state["singularities"] == [], state)

    # a line field with its own singularities: a trivial connection of order 2
    status, state, data = server.edit({"op": "field", "kind": "trivial", "order": 2})
    field_singular = dict((f, k) for f, k in state["field_singularities"]) if status == 200 else {}
    check("trivial line field: +1/2 singularities summing to chi", status == 200 and sum(field_singular.values()) == 4
          and all(k == 1 for k in field_singular.values()), state)
    check("trivial line field: its branch faces are exactly the prescribed singularities",
          dict((f, k) for f, k in state["branch_faces"]) == field_singular, (state["branch_faces"], field_singular))
    spare = [f for f in range(5, nf, 71) if f not in field_singular][:3]
    status, state, data = server.edit({"op": "add_field_pair", "plus": spare[0], "minus": spare[1]})
    field_singular = dict((f, k) for f, k in state["field_singularities"]) if status == 200 else {}
    check("trivial line field: a +1/2 -1/2 pair", status == 200 and field_singular.get(spare[0]) == 1 and
          field_singular.get(spare[1]) == -1 and dict((f, k) for f, k in state["branch_faces"]) == field_singular, state)
    status, state, data = server.edit({"op": "move_field_singularity", "from": spare[1], "to": spare[2]})
    field_singular = dict((f, k) for f, k in state["field_singularities"]) if status == 200 else {}
    check("trivial line field: drag the -1/2", status == 200 and field_singular.get(spare[2]) == -1 and
          spare[1] not in field_singular and dict((f, k) for f, k in state["branch_faces"]) == field_singular, state)
    worst, wound = corner_readings(mesh, state, data)
    check("trivial line field: the stripes follow, continuous", worst < 1e-3 and wound == {}, (worst, wound))
    expect_refused(server, {"op": "annihilate_field", "a": spare[0], "b": min(f for f in field_singular if f != spare[0] and
                                                                              field_singular[f] == 1)},
                   ["opposite"], "annihilating two +1/2")
    status, state, data = server.edit({"op": "annihilate_field", "a": spare[0], "b": spare[2]})
    check("trivial line field: annihilate the pair", status == 200 and len(state["field_singularities"]) == 4 and
          spare[0] not in dict((f, k) for f, k in state["field_singularities"]), state)
    expect_refused(server, {"op": "field", "kind": "smoothest", "order": 3}, ["order"], "a field of order 3")
    expect_refused(server, {"op": "field", "kind": "heat", "vertex": 0, "order": 2}, ["vector field"], "a heat line field")
    expect_refused(server, {"op": "field", "kind": "principal", "order": 4}, ["line field"], "a principal cross field")
    status, state, _ = server.edit({"op": "field", "kind": "principal"})
    check("principal curvature line field", status == 200 and state["order"] == 2 and state["field"]["kind"] == "principal", state)
    expect_refused(server, {"op": "add_field_pair", "plus": 1, "minus": 2}, ["trivial"], "a field pair without a trivial connection")

    # back to a vector field: one family, no overlay, the vector PLY
    status, state, data = server.edit({"op": "field", "kind": "axis", "axis": [0, 1, 0]})
    check("back to a vector field", status == 200 and state["order"] == 1 and state["overlay"] == 0 and len(data) == 3 * nf
          and state["singularities"] == [], state)
    expect_refused(server, {"op": "automatic"}, ["vector field"], "automatic singularities on a vector field")


def main():
    editor, data = sys.argv[1:3]
    bunny = os.path.join(data, "bunny_8k.off")
    with open(bunny) as f:
        header = f.readline() and f.readline().split()
    server = Server(editor, bunny)
    try:
        run(server, data, int(header[0]), int(header[1]))
    finally:
        alive = server.alive()
        server.stop()
        if not alive or failed:
            print("the server printed:\n" + server.output())
    check("the server is still running after all the requests", alive)
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


def run(server, data, nv, nf):
    hostile_requests(server)
    mesh = server.json("api/mesh")
    check("mesh: counts of the file", mesh["vertices"] == nv and mesh["faces"] == nf, (mesh["vertices"], mesh["faces"]))
    check("mesh: positions and triangles", len(mesh["positions"]) == 3 * nv and len(mesh["triangles"]) == 3 * nf
          and max(mesh["triangles"]) < nv)
    check("mesh: the bunny is closed, of Euler characteristic 2",
          mesh["boundary_faces"] == [] and mesh["closed_components_euler"] == [2])
    state, corners = server.state()
    check("state: no singularity at first", state["singularities"] == [])
    check("state: three finite corner values per face", len(corners) == 3 * nf and all(map(math.isfinite, corners)))

    # the per-corner data and the exported alpha describe the same stripes
    found, alpha, faces, _ = windings(server)
    check("no singularity in the exported alpha at first", found == {}, found)
    worst = max(abs(math.cos(corners[3 * f + k]) - math.cos(alpha[faces[f][k]])) for f in range(nf) for k in range(3))
    check("cos of the corner data = cos alpha at the corner's vertex", worst < 1e-5, worst)

    # a pair, then a move, then the annihilation: the windings of alpha follow exactly
    status, state, _ = server.edit({"op": "add_pair", "plus": 1000, "minus": 5000})
    check("add_pair", status == 200 and singularities(state) == {1000: 1, 5000: -1}, state)
    check("add_pair: the server reports its time", state["timing"]["server_ms"] >= state["timing"]["solve_ms"] > 0)
    found, _, _, index = windings(server)
    check("the exported alpha winds +1 and -1 exactly around the two faces", found == {1000: 1, 5000: -1}, found)
    check("the exported indices are the prescribed ones", {f: k for f, k in enumerate(index) if k} == {1000: 1, 5000: -1})
    ring = [f for f, tri in enumerate(faces) if len(set(tri) & set(faces[5000])) == 2]
    status, state, _ = server.edit({"op": "move", "from": 5000, "to": ring[0]})
    check("move to a neighbour", status == 200 and singularities(state) == {1000: 1, ring[0]: -1}, state)
    status, state, _ = server.edit({"op": "move", "from": ring[0], "to": 3000})
    check("move far", status == 200 and singularities(state) == {1000: 1, 3000: -1}, state)
    found, _, _, _ = windings(server)
    check("after the moves alpha winds around the new face only", found == {1000: 1, 3000: -1}, found)
    version = state["version"]

    # refused requests: a message, and nothing changes
    expect_refused(server, {"op": "add", "face": 7, "index": 1}, ["sum", "pairs"], "a single +1 on a closed surface")
    expect_refused(server, {"op": "add", "face": 10 ** 9, "index": 1}, ["not a face"], "an unknown face")
    expect_refused(server, {"op": "add", "face": -1, "index": 1}, ["not a face"], "a negative face")
    expect_refused(server, {"op": "add", "face": "7", "index": 1}, ["face"], "a face given as a string")
    expect_refused(server, {"op": "add", "face": 7.5, "index": 1}, ["face"], "a fractional face")
    expect_refused(server, {"op": "add", "face": 7, "index": 9}, ["out of range"], "an index of 9")
    expect_refused(server, {"op": "add", "face": 7}, ["missing", "index"], "a missing index")
    expect_refused(server, '{"op": "add", "face": ', ["malformed JSON"], "malformed JSON")
    expect_refused(server, "[1, 2]", ["JSON object"], "JSON that is not an object")
    expect_refused(server, {"op": "explode"}, ["unknown op"], "an unknown op")
    expect_refused(server, {"op": 3}, ["op", "string"], "an op that is not a string")
    expect_refused(server, {"op": "load", "name": 3}, ["name", "string"], "a mesh name that is not a string")
    expect_refused(server, "[" * 30000 + "]" * 30000, ["JSON object"], "JSON nested 30000 deep")
    expect_refused(server, {"op": "move", "from": 7, "to": 8}, ["holds no singularity"], "moving an empty face")
    expect_refused(server, {"op": "annihilate", "a": 1000, "b": 1001}, ["annihilat"], "annihilating a lone singularity")
    expect_refused(server, {"op": "frequency", "stripes": 0}, ["stripes"], "zero stripes")
    expect_refused(server, {"op": "frequency", "stripes": 1e6}, ["stripes"], "more stripes than the mesh resolves")
    expect_refused(server, '{"op": "frequency", "stripes": 1e999}', ["1e999"], "infinitely many stripes")
    expect_refused(server, {"op": "field", "kind": "magnetic"}, ["unknown field"], "an unknown field")
    expect_refused(server, {"op": "field", "kind": "axis", "axis": [0, 0, 0]}, ["no direction"], "a zero axis")
    expect_refused(server, {"op": "field", "kind": "heat", "vertex": nv}, ["vertex", "out of range"], "a heat source out of range")
    expect_refused(server, {"op": "move_field_singularity", "from": 1, "to": 2}, ["trivial"], "a field singularity without a trivial connection")
    expect_refused(server, {"op": "load", "name": "../../etc/passwd"}, ["unknown mesh"], "loading a mesh that is not offered")
    expect_refused(server, {"op": "load", "name": "degtri_four.off"}, ["cannot edit", "degenerate"], "loading a mesh with degenerate faces")
    status, _, body = server.request("POST", "api/edit", '{"op": "state", "pad": "' + "x" * 200000 + '"}')
    check("a huge payload is refused", status == 413, status)
    status, _, body = server.request("GET", "api/nothing")
    check("an unknown path: 404 with a JSON message", status == 404 and "error" in json.loads(body), (status, body[:100]))
    status, _, body = server.request("POST", "api/frame?name=x", b"\x89PNG\r\n\x1a\n", "image/png")
    check("frames are refused without --save-frames", status == 404, status)
    state, _ = server.state()
    check("refusals do not count as edits", state["version"] == version, (state["version"], version))

    # the frequency: twice the stripes, twice the 1-form, four times the energy of a straight field
    server.edit({"op": "annihilate", "a": 1000, "b": 3000})
    status, state, _ = server.edit({"op": "field", "kind": "axis", "axis": [1, 0, 0]})
    check("field along X", status == 200 and state["field"]["kind"] == "axis", state)
    e1 = state["energy"]
    status, state2, _ = server.edit({"op": "frequency", "stripes": 2 * state["stripes"]})
    check("frequency x2", status == 200 and abs(state2["stripes"] - 2 * state["stripes"]) < 1e-9)
    check("energy scales with the square of the frequency (no singularity: one quadratic solve)",
          abs(state2["energy"] - 4 * e1) <= 1e-6 * abs(4 * e1), (e1, state2["energy"]))

    # the other fields
    status, state, _ = server.edit({"op": "field", "kind": "smoothest"})
    check("smoothest field", status == 200 and state["field"]["kind"] == "smoothest")
    status, state, _ = server.edit({"op": "field", "kind": "heat", "vertex": 0, "degrees": 45})
    check("heat spiral", status == 200 and state["field"] == {"kind": "heat", "order": 1, "vertex": 0, "degrees": 45.0}, state["field"])
    status, state, _ = server.edit({"op": "field", "kind": "trivial"})
    field_singular = dict((f, k) for f, k in state["field_singularities"]) if status == 200 else {}
    check("trivial connection: its singularities sum to the Euler characteristic",
          status == 200 and sum(field_singular.values()) == 2, state)
    first = min(field_singular)
    target = next(f for f in range(nf) if f not in field_singular)
    status, state, _ = server.edit({"op": "move_field_singularity", "from": first, "to": target})
    moved = dict((f, k) for f, k in state["field_singularities"]) if status == 200 else {}
    check("move a field singularity", status == 200 and target in moved and first not in moved, state)

    # several clients at once: the server serializes the edits, each one exactly once, and the
    # final state is the one of the last edit it applied
    errors, answers = [], []
    before, _ = server.state()

    def client(i):
        for j in range(10):
            status, state, _ = server.edit({"op": "frequency", "stripes": 3 + (i + j) % 5 + i / 10})
            if status != 200:
                errors.append(state)
            else:
                answers.append((state["version"], state["stripes"]))
            server.state()

    threads = [threading.Thread(target=client, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    check("40 concurrent edits from 4 clients", errors == [], errors[:3])
    after, corners = server.state()
    versions = sorted(v for v, _ in answers)
    check("the 40 edits were applied one after the other, each once",
          versions == list(range(before["version"] + 1, before["version"] + 41)), versions)
    check("the final state is the last applied edit's", after["version"] == before["version"] + 40 and
          after["stripes"] == max(answers)[1], (after["version"], after["stripes"], max(answers)))
    check("the concurrent edits kept the singularities and the field",
          after["singularities"] == before["singularities"] and after["field"] == before["field"] and
          after["field_singularities"] == before["field_singularities"])
    check("the final corner data is finite", all(map(math.isfinite, corners)))

    line_and_cross_fields(server)

    # another mesh: with boundary, a single +1 is fine, but not on a boundary face
    status, state, _ = server.edit({"op": "load", "name": "elephant-with-holes.off"})
    mesh = server.json("api/mesh")
    check("load another mesh", status == 200 and state["mesh"] == "elephant-with-holes.off" and
          state["mesh_version"] == 2 and mesh["faces"] == state["faces"], state)
    boundary = set(mesh["boundary_faces"])
    inner = next(f for f in range(mesh["faces"]) if f not in boundary)
    status, state, _ = server.edit({"op": "add", "face": inner, "index": 1})
    check("a single +1 on a mesh with boundary", status == 200 and singularities(state) == {inner: 1}, state)
    found, _, faces, _ = windings(server)
    # on this coarse mesh an edge next to the singularity can carry |dalpha| > pi, and the wrapped
    # alpha then shows the winding in a face sharing a vertex (the stripes program notes the same)
    check("alpha winds once, at the face or a face touching it",
          sum(found.values()) == 1 and all(set(faces[f]) & set(faces[inner]) for f in found), (inner, found))
    expect_refused(server, {"op": "add", "face": min(boundary), "index": -1}, ["boundary"], "a singularity on a boundary face")

    # a closed surface of Euler characteristic 0: stripe indices still sum to 0 there
    status, state, _ = server.edit({"op": "load", "name": "torus.off"})
    mesh = server.json("api/mesh")
    check("the torus is closed, of Euler characteristic 0", status == 200 and mesh["closed_components_euler"] == [0], mesh["closed_components_euler"])
    expect_refused(server, {"op": "add", "face": 0, "index": 1}, ["sum", "pairs"], "a single +1 on the torus")
    status, state, _ = server.edit({"op": "field", "kind": "trivial"})
    check("trivial connection on the torus: no singularity needed", status == 200 and state["field_singularities"] == [], state)

    quad_preview(server)
    quad_preview_with_boundary(server)


def read_quad_off(text):
    """(points, faces) of an OFF file."""
    items = [line for line in text.splitlines() if line.strip() and not line.startswith("#")]
    assert items[0].strip() == "OFF"
    nv, nf = (int(x) for x in items[1].split()[:2])
    points = [tuple(float(x) for x in line.split()) for line in items[2:2 + nv]]
    faces = [tuple(int(x) for x in line.split()[1:]) for line in items[2 + nv:2 + nv + nf]]
    return points, faces


def directed_edges(faces):
    """(how many faces run along each directed edge, whether every face is a quad)."""
    directed = {}
    for face in faces:
        for i in range(len(face)):
            key = (face[i], face[(i + 1) % len(face)])
            directed[key] = directed.get(key, 0) + 1
    return directed, all(len(face) == 4 for face in faces)


def quad_mesh_reading(points, faces):
    """An independent reading of a closed quad mesh: (only quads, every edge in two faces once each
    way, Euler characteristic, valence per vertex)."""
    directed, quads = directed_edges(faces)
    two_sided = all(n == 1 and directed.get((b, a)) == 1 for (a, b), n in directed.items())
    edges = len(directed) // 2
    valence = [0] * len(points)
    for a, b in directed:
        valence[a] += 1
    return quads, two_sided, len(points) - edges + len(faces), valence


def quad_vertices_on_the_lattice(server, points, step=5):
    """For every `step`-th quad vertex: max(|u|, |v|) mod 2 pi there, read from the state's corner
    data (linear in the regular input face the vertex projects into; vertices in or next to branch
    faces, where no such face holds them, are left out). Sorted."""
    mesh = server.json("api/mesh")
    P, T, nf = mesh["positions"], mesh["triangles"], mesh["faces"]
    state, data = server.state()
    u, v = data[:3 * nf], data[3 * nf:6 * nf]
    branch = {f for f, _ in state["branch_faces"]}

    def sub(a, b):
        return [a[i] - b[i] for i in range(3)]

    def dot(a, b):
        return sum(a[i] * b[i] for i in range(3))

    V = [P[3 * i:3 * i + 3] for i in range(len(P) // 3)]
    F = [T[3 * f:3 * f + 3] for f in range(nf)]
    centre = [[sum(V[k][i] for k in F[f]) / 3 for i in range(3)] for f in range(nf)]
    off = []
    for p in points[::step]:
        for f in sorted(range(nf), key=lambda f: dot(sub(centre[f], p), sub(centre[f], p)))[:12]:
            if f in branch:
                continue
            a, b, c = (V[k] for k in F[f])
            e0, e1, e2 = sub(b, a), sub(c, a), sub(p, a)
            d00, d01, d11, d20, d21 = dot(e0, e0), dot(e0, e1), dot(e1, e1), dot(e2, e0), dot(e2, e1)
            den = d00 * d11 - d01 * d01
            y, z = (d11 * d20 - d01 * d21) / den, (d00 * d21 - d01 * d20) / den
            x = 1 - y - z
            if min(x, y, z) > -1e-6:
                uu = x * u[3 * f] + y * u[3 * f + 1] + z * u[3 * f + 2]
                vv = x * v[3 * f] + y * v[3 * f + 1] + z * v[3 * f + 2]
                off.append(max(abs(wrap(uu)), abs(wrap(vv))))
                break
    return sorted(off)


def quad_preview(server):
    """The cross field's quad preview: the quads of the two families' lines after every edit, their
    irregular vertices the cones (read from the exported OFF alone), updated when a cone moves,
    exported as OFF and OBJ; refusals leave the state as it was."""
    # the torus (Euler characteristic 0): a cross field without cones gives a regular grid
    status, state, data = server.edit({"op": "field", "kind": "trivial", "order": 4})
    check("quads: a cross field on the torus", status == 200 and state["order"] == 4 and state["quads"] == {"on": False},
          state)
    status, _, body = server.request("GET", "api/export_quads.off")
    check("quads: no export while the preview is off", status == 409 and b"off" in body, (status, body[:200]))
    status, state, data = server.edit({"op": "frequency", "stripes": 8})
    status, state, data = server.edit({"op": "quads", "on": True})
    nf = state["faces"] if status == 200 else 0
    check("quads: the torus's preview is a quad mesh without irregular vertex",
          status == 200 and state["quads"]["on"] and state["quads"]["valid"] and
          state["quads"]["irregular_vertices"] == 0 and state["quads"]["faces"] > 20, state)
    check("quads: the state's data ends with the quad edges",
          status == 200 and len(data) == 3 * nf * 2 + 15 * state["overlay"] + 6 * state["quad_edges"] and
          state["quad_edges"] == 2 * state["quads"]["faces"], state if status != 200 else len(data))
    status, _, body = server.request("GET", "api/export_quads.off")
    check("quads: exported as OFF", status == 200, (status, body[:200]))
    if status == 200:
        points, faces = read_quad_off(body.decode())
        quads, two_sided, chi, valence = quad_mesh_reading(points, faces)
        check("quads: the torus's OFF: quads, closed, Euler characteristic 0, valence 4 everywhere",
              quads and two_sided and chi == 0 and set(valence) == {4} and len(faces) == state["quads"]["faces"],
              (quads, two_sided, chi, set(valence)))
    status, _, body = server.request("GET", "api/export_quads.obj")
    text = body.decode() if status == 200 else ""
    check("quads: exported as OBJ, the same mesh",
          status == 200 and sum(line.startswith("f ") for line in text.splitlines()) == state["quads"]["faces"] and
          all(len(line.split()) == 5 for line in text.splitlines() if line.startswith("f ")), (status, text[:200]))

    # refused, the state as it was: rounds out of range, "on" not a boolean, a stripe singularity
    # (a T-junction) while the preview is on
    expect_refused(server, {"op": "quads", "on": True, "rounds": 65}, ["rounds", "range"], "quads: 65 rounds")
    expect_refused(server, {"op": "quads", "on": 1}, ["true or false"], "quads: \"on\" = 1")
    expect_refused(server, {"op": "add_pair", "plus": 0, "minus": nf // 2}, ["T-junction"],
                   "quads: a stripe singularity pair while the preview is on")

    # a 1k egg (genus 0; light enough for the sanitizers): the trivial cross field's 8 cones of +1/4
    # are the 8 vertices of valence 3
    status, state, _ = server.edit({"op": "load", "name": "egg_1k.off"})
    status, state, _ = server.edit({"op": "field", "kind": "trivial", "order": 4})
    check("quads: off after loading a mesh, 8 cones on the egg",
          status == 200 and state["quads"] == {"on": False} and len(state["field_singularities"]) == 8, state)
    status, state, _ = server.edit({"op": "frequency", "stripes": 10})
    status, state, data = server.edit({"op": "quads", "on": True})
    check("quads: the egg's preview", status == 200 and state["quads"]["valid"], state)

    def read_exported(label, cones):
        status, _, body = server.request("GET", "api/export_quads.off")
        if status != 200:
            check(label, False, (status, body[:300]))
            return
        points, faces = read_quad_off(body.decode())
        quads, two_sided, chi, valence = quad_mesh_reading(points, faces)
        irregular = sorted(v for v in valence if v != 4)
        check(label, quads and two_sided and chi == 2 and irregular == [3] * cones,
              (quads, two_sided, chi, irregular))

    if status == 200 and state["quads"]["valid"]:
        read_exported("quads: the egg's OFF: quads, closed, Euler characteristic 2, valence 3 at 8 vertices "
                      "(the cones), 4 elsewhere", 8)
        # a cone dragged to a neighbouring face: the preview follows
        mesh = server.json("api/mesh")
        T = mesh["triangles"]
        cone = state["field_singularities"][0][0]
        taken = {f for f, _ in state["field_singularities"]}
        neighbour = next(f for f in range(mesh["faces"]) if f not in taken and f != cone and
                         len(set(T[3 * f:3 * f + 3]) & set(T[3 * cone:3 * cone + 3])) == 2)
        status, state, _ = server.edit({"op": "move_field_singularity", "from": cone, "to": neighbour})
        check("quads: a cone moved, the preview updated with it", status == 200 and state["quads"]["on"] and
              neighbour in {f for f, _ in state["field_singularities"]} and "quads_ms" in state["timing"], state)
        if status == 200 and state["quads"]["valid"]:
            read_exported("quads: after the move, still 8 vertices of valence 3", 8)
            # the exported vertices are where both stripe angles of the same solve are 0 mod 2 pi
            status, _, body = server.request("GET", "api/export_quads.off")
            points, _ = read_quad_off(body.decode())
            off = quad_vertices_on_the_lattice(server, points)
            check("quads: the vertices lie where u = v = 0 mod 2 pi (90% within 1e-4 rad)",
                  len(off) > len(points) // 10 and off[int(0.9 * len(off))] < 1e-4,
                  (len(off), off[len(off) // 2] if off else None, off[int(0.9 * len(off))] if off else None))
        elif status == 200:
            check("quads: a failed preview says why", "quad mesh" in state["quads"]["problem"], state["quads"])
    # the trivial connection with the smoothest cross field's cones, moved h apart (as quad_remesh)
    expect_refused(server, {"op": "field", "kind": "trivial", "order": 4, "cones": "random"}, ["spread", "smoothest"],
                   "a trivial field's cones neither spread nor smoothest")
    status, state, _ = server.edit({"op": "field", "kind": "trivial", "order": 4, "cones": "smoothest"})
    check("quads: the smoothest field's cones, summing to 4 chi = 8 quarters, the preview still on",
          status == 200 and state["field"].get("cones") == "smoothest" and
          sum(k for _, k in state["field_singularities"]) == 8 and state["quads"]["on"] and
          sorted(state["field_singularities"]) == sorted(state["branch_faces"]), state)
    status, state, data = server.edit({"op": "quads", "on": False})
    check("quads: off again, no edges", status == 200 and state["quads"] == {"on": False} and state["quad_edges"] == 0,
          state)
    status, state, _ = server.edit({"op": "field", "kind": "smoothest", "order": 2})
    expect_refused(server, {"op": "quads", "on": True}, ["cross field"], "quads on a line field")


def quad_mesh_with_boundary_reading(points, faces):
    """An independent reading of a quad mesh with a boundary: (only quads, every directed edge once
    and every edge in at most two faces, Euler characteristic, number of boundary loops, valence
    per vertex, whether each vertex is on the boundary)."""
    directed, quads = directed_edges(faces)
    manifold = all(n == 1 for n in directed.values())
    undirected = {tuple(sorted(k)) for k in directed}
    border = {(a, b) for (a, b) in directed if (b, a) not in directed}  # the face is on the left
    nxt = {}
    for a, b in border:
        manifold = manifold and b not in nxt  # one boundary edge into each boundary vertex
        nxt[b] = a
    loops, seen = 0, set()
    for start in nxt:
        if start in seen:
            continue
        loops += 1
        v = start
        while v not in seen:
            seen.add(v)
            v = nxt[v]
    valence = [0] * len(points)
    for a, b in undirected:
        valence[a] += 1
        valence[b] += 1
    on_boundary = [v in nxt for v in range(len(points))]
    return quads, manifold, len(points) - len(undirected) + len(faces), loops, valence, on_boundary


def quad_preview_with_boundary(server):
    """The quad preview on a mesh with a boundary: a plate with two square holes (3 loops, Euler
    characteristic -1, 4 convex and 8 concave corners). The quads follow every loop when the cross
    field follows the boundary; otherwise the preview is refused, saying how to get such a field."""
    status, state, _ = server.edit({"op": "load", "name": "holed_plate.off"})
    check("quads with a boundary: the plate loaded", status == 200, state)
    status, state, _ = server.edit({"op": "field", "kind": "trivial", "order": 4, "cones": "smoothest"})
    check("quads with a boundary: a trivial cross field, free along the boundary", status == 200 and
          "boundary" not in state["field"], state)
    expect_refused(server, {"op": "quads", "on": True}, ["boundary", "tangent"],
                   "quads on a mesh with a boundary that the field does not follow")
    expect_refused(server, {"op": "field", "kind": "trivial", "order": 4, "boundary": "tangent"}, ["cones", "smoothest"],
                   "a trivial field along the boundary with spread cones")
    expect_refused(server, {"op": "field", "kind": "axis", "axis": [0, 1, 0], "boundary": "tangent"}, ["tangent", "axis"],
                   "an axis field along the boundary")
    expect_refused(server, {"op": "field", "kind": "smoothest", "order": 4, "boundary": "normal"}, ["free", "tangent"],
                   "an unknown boundary condition")
    status, state, _ = server.edit({"op": "field", "kind": "trivial", "order": 4, "cones": "smoothest",
                                    "boundary": "tangent"})
    check("quads with a boundary: the cross field along the boundary, its cones summing to 0 here "
          "(4 chi, less the 4 convex corners, plus the 8 concave ones)", status == 200 and
          state["field"].get("boundary") == "tangent" and sum(k for _, k in state["field_singularities"]) == 0, state)
    cones = len(state["field_singularities"]) if status == 200 else 0
    status, state, _ = server.edit({"op": "frequency", "stripes": 12})
    status, state, _ = server.edit({"op": "quads", "on": True})
    check("quads with a boundary: the preview follows the 3 loops", status == 200 and state["quads"]["valid"] and
          state["quads"].get("boundary_loops") == 3 and state["quads"]["irregular_vertices"] == cones, state)
    status, _, body = server.request("GET", "api/export_quads.off")
    if status == 200:
        points, faces = read_quad_off(body.decode())
        quads, manifold, chi, loops, valence, on_boundary = quad_mesh_with_boundary_reading(points, faces)
        inner = sorted(valence[v] for v in range(len(points)) if not on_boundary[v] and valence[v] != 4)
        corners = sorted(valence[v] for v in range(len(points)) if on_boundary[v] and valence[v] != 3)
        check("quads with a boundary: the OFF read alone: quads, manifold, Euler characteristic -1, 3 loops, "
              "the corners (valence 2 at the 4 convex ones, 4 at the 8 concave ones), regular inside but at cones",
              quads and manifold and chi == -1 and loops == 3 and corners == [2] * 4 + [4] * 8 and len(inner) == cones,
              (quads, manifold, chi, loops, corners, inner))
    else:
        check("quads with a boundary: exported", False, (status, body[:200]))
    # a field singularity in a face on the boundary is refused (the field's direction is fixed
    # there); a pair inside is accepted and the preview follows (or says why not)
    mesh = server.json("api/mesh")
    T, nf = mesh["triangles"], mesh["faces"]
    count = {}
    for f in range(nf):
        for i in range(3):
            e = tuple(sorted((T[3 * f + i], T[3 * f + (i + 1) % 3])))
            count[e] = count.get(e, 0) + 1
    on_border = [any(count[tuple(sorted((T[3 * f + i], T[3 * f + (i + 1) % 3])))] == 1 for i in range(3))
                 for f in range(nf)]
    outer = next(f for f in range(nf) if on_border[f])
    inside = [f for f in range(nf) if not on_border[f]]
    expect_refused(server, {"op": "add_field_pair", "plus": outer, "minus": inside[len(inside) // 2]},
                   ["boundary", str(outer)], "a field singularity in a face on the boundary")
    status, state, _ = server.edit({"op": "add_field_pair", "plus": inside[len(inside) // 3],
                                    "minus": inside[2 * len(inside) // 3]})
    check("quads with a boundary: a cone pair inside, the preview updated",
          status == 200 and state["quads"]["on"] and len(state["field_singularities"]) == cones + 2 and
          (state["quads"]["valid"] and state["quads"]["irregular_vertices"] == cones + 2 or
           "quad mesh" in state["quads"].get("problem", "")), state)
    # with the preview on, a field that does not follow the boundary is refused; switched off, it is not
    expect_refused(server, {"op": "field", "kind": "smoothest", "order": 4}, ["boundary", "off"],
                   "a free cross field while the preview follows the boundary")
    status, state, _ = server.edit({"op": "quads", "on": False})
    status, state, _ = server.edit({"op": "field", "kind": "smoothest", "order": 4})
    check("quads with a boundary: off, then any field", status == 200 and state["quads"] == {"on": False}, state)


if __name__ == "__main__":
    sys.exit(main())
