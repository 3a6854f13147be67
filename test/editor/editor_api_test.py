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


def singularities(state):
    return {f: k for f, k in state["singularities"]}


def expect_refused(server, request, words, what):
    """The request gets a 4xx with a message containing all `words`, and the state is unchanged."""
    before = server.state()
    status, message, _ = server.edit(request)
    check(f"{what}: refused", 400 <= status < 500, f"status {status}")
    text = message if isinstance(message, str) else json.dumps(message)
    check(f"{what}: the message says why", all(w.lower() in text.lower() for w in words), text)
    after = server.state()
    same = before[0]["singularities"] == after[0]["singularities"] and before[1] == after[1] and \
        before[0]["field"] == after[0]["field"] and before[0]["stripes"] == after[0]["stripes"]
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
    check("heat spiral", status == 200 and state["field"] == {"kind": "heat", "vertex": 0, "degrees": 45.0}, state["field"])
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

    # another mesh: with boundary, a single +1 is fine, but not on a boundary face
    status, state, _ = server.edit({"op": "load", "name": "elephant-with-holes.off"})
    mesh = server.json("api/mesh")
    check("load another mesh", status == 200 and state["mesh"] == "elephant-with-holes.off" and
          state["mesh_version"] == 1 and mesh["faces"] == state["faces"], state)
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


if __name__ == "__main__":
    sys.exit(main())
