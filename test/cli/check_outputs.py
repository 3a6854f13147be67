# Copyright (c) 2026 The CGAL Surface Design authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks that the files a command-line program wrote are what their names promise: each exists,
is not empty, and parses completely:
- OFF, OBJ, PLY (ASCII or binary little-endian): the counts of the header are the elements in
  the file, every coordinate is finite, every face has at least 3 vertices, all within range;
- SVG: well-formed XML whose root is <svg> with at least one drawn element;
- PDF: every cross-reference offset at its object, every stream as long as its /Length, a page;
- VTK (legacy ASCII POLYDATA, the pictures' surface files): the counts of POINTS, POLYGONS and
  POINT_DATA are the values given, every number finite, every polygon's indices within range;
- PNG: the signature, an IHDR chunk of non-zero size, and an IEND chunk, every chunk CRC correct;
- TXT, CSV, JSON: non-empty text (JSON: parses).
usage: check_outputs.py FILE...      (exit 1 with one line per bad file)
       check_outputs.py --self-test  (broken files of each kind must be rejected)"""

import json
import math
import os
import struct
import sys
import xml.etree.ElementTree as ET
import zlib


class Bad(Exception):
    pass


def finite(values, what):
    for v in values:
        if not math.isfinite(v):
            raise Bad(f"a non-finite {what}: {v}")


def check_faces(faces, nv):
    for f in faces:
        if len(f) < 3:
            raise Bad(f"a face with {len(f)} vertices")
        if min(f) < 0 or max(f) >= nv:
            raise Bad(f"a face index out of range (0..{nv - 1}): {f}")
        if len(set(f)) != len(f):
            raise Bad(f"a face that repeats a vertex: {f}")


def check_off(data):
    lines = [line.split("#", 1)[0].split() for line in data.decode().splitlines()]
    lines = [items for items in lines if items]
    if not lines or not lines[0][0].endswith("OFF"):
        raise Bad("no OFF header")
    counts = lines[0][1:] if len(lines[0]) > 1 else lines.pop(1)
    nv, nf = int(counts[0]), int(counts[1])
    if len(lines) != 1 + nv + nf:
        raise Bad(f"{nv} vertices and {nf} faces announced, {len(lines) - 1} lines given")
    for items in lines[1:1 + nv]:
        finite([float(x) for x in items[:3]], "coordinate")
    faces = []
    for items in lines[1 + nv:]:
        k = int(items[0])
        if len(items) < 1 + k:
            raise Bad(f"a face of {k} vertices with {len(items) - 1} indices")
        faces.append([int(x) for x in items[1:1 + k]])  # anything after: the face's colour
    check_faces(faces, nv)
    return nv, nf


def check_obj(data):
    nv, faces, polylines = 0, [], []
    for line in data.decode().splitlines():
        items = line.split()
        if not items:
            continue
        if items[0] == "v":
            finite([float(x) for x in items[1:4]], "coordinate")
            nv += 1
        elif items[0] == "f":
            faces.append([int(x.split("/")[0]) - 1 for x in items[1:]])
        elif items[0] == "l":
            polylines.append([int(x.split("/")[0]) - 1 for x in items[1:]])
    if nv == 0:
        raise Bad("no vertex")
    check_faces(faces, nv)
    for line in polylines:  # a polyline: at least two points, indices in range, no zero-length step
        if len(line) < 2 or min(line) < 0 or max(line) >= nv:
            raise Bad(f"a polyline of {len(line)} points with indices out of range (0..{nv - 1}): {line[:8]}")
        if any(a == b for a, b in zip(line, line[1:])):
            raise Bad(f"a polyline that repeats a point in a row: {line[:8]}")
    if not faces and not polylines:
        raise Bad("neither faces nor polylines")
    return nv, len(faces)


PLY_TYPES = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h", "ushort": "H",
             "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I", "float": "f", "float32": "f",
             "double": "d", "float64": "d"}


def check_ply(data):
    end = data.find(b"end_header\n")
    if not data.startswith(b"ply\n") or end < 0:
        raise Bad("no PLY header")
    header = data[:end].decode().splitlines()
    body = data[end + len(b"end_header\n"):]
    fmt = next(line.split()[1] for line in header if line.startswith("format"))
    elements = []
    for line in header:
        items = line.split()
        if items[0] == "element":
            elements.append((items[1], int(items[2]), []))
        elif items[0] == "property":
            elements[-1][2].append(items[1:])
    counts = {name: count for name, count, _ in elements}
    if fmt == "ascii":
        lines = body.decode().split("\n")
        at = 0
        faces, positions, face_rows = [], [], []
        for name, count, props in elements:
            for _ in range(count):
                if at >= len(lines):
                    raise Bad(f"{count} {name} elements announced, fewer given")
                values = lines[at].split()
                at += 1
                k = 0
                row = []
                for prop in props:
                    if prop[0] == "list":
                        n = int(values[k])
                        items = values[k + 1:k + 1 + n]
                        if len(items) != n:
                            raise Bad(f"a {name} list announces {n} values, gives {len(items)}")
                        if prop[2] in ("char", "uchar", "short", "ushort", "int", "uint", "int8", "uint8", "int32"):
                            row.append([int(x) for x in items])
                        else:
                            floats = [float(x) for x in items]
                            finite(floats, prop[3])
                            row.append(floats)
                        k += 1 + n
                    else:
                        row.append(float(values[k]))
                        k += 1
                if name == "vertex":
                    finite(row[:3], "coordinate")
                    positions.append(row)
                elif name == "face":
                    faces.append(row[0])
                    face_rows.append(dict(zip([prop[-1] for prop in props], row)))
        if any(line.strip() for line in lines[at:]):
            raise Bad("data after the last element")
        if face_rows and "corner_alpha" in face_rows[0]:
            check_stripe_corners(faces, face_rows)
    elif fmt == "binary_little_endian":
        at = 0
        faces, positions = [], []
        for name, count, props in elements:
            for _ in range(count):
                row = []
                for prop in props:
                    if prop[0] == "list":
                        (n,) = struct.unpack_from("<" + PLY_TYPES[prop[1]], body, at)
                        at += struct.calcsize(PLY_TYPES[prop[1]])
                        t = "<%d%s" % (n, PLY_TYPES[prop[2]])
                        row.append(list(struct.unpack_from(t, body, at)))
                        at += struct.calcsize(t)
                    else:
                        t = "<" + PLY_TYPES[prop[0]]
                        row.append(struct.unpack_from(t, body, at)[0])
                        at += struct.calcsize(t)
                if name == "vertex":
                    finite(row[:3], "coordinate")
                    positions.append(row)
                elif name == "face":
                    faces.append(row[0])
        if at != len(body):
            raise Bad(f"{len(body) - at} bytes after the last element")
    else:
        raise Bad(f"unsupported PLY format {fmt}")
    check_faces(faces, counts.get("vertex", 0))
    return counts.get("vertex", 0), counts.get("face", 0)


def check_stripe_corners(faces, rows):
    """A stripe pattern's per-corner angles (corner_alpha, and corner_beta for a cross field) are
    one continuous pattern: at every vertex, the corners of all faces around it agree modulo 2 pi,
    up to the field's symmetry (a sign for a line field, a quarter turn of the two families for a
    cross field)."""
    two_pi = 2 * math.pi
    cross = "corner_beta" in rows[0]
    at_vertex = {}
    for face, row in zip(faces, rows):
        alpha = row["corner_alpha"]
        beta = row["corner_beta"] if cross else [0.0] * len(alpha)
        if len(alpha) != len(face) or len(beta) != len(face):
            raise Bad(f"corner_alpha of {len(alpha)} values on a face of {len(face)} corners")
        for v, a, b in zip(face, alpha, beta):
            at_vertex.setdefault(v, []).append((a, b))

    def wrapped(x):
        return abs((x + math.pi) % two_pi - math.pi)

    symmetries = [lambda a, b: (a, b), lambda a, b: (-a, -b)]
    if cross:
        symmetries += [lambda a, b: (b, -a), lambda a, b: (-b, a)]
    for v, values in at_vertex.items():
        a0, b0 = values[0]
        for a, b in values[1:]:
            if min(max(wrapped(x - a0), wrapped(y - b0)) for x, y in (f(a, b) for f in symmetries)) > 1e-3:
                raise Bad(f"the stripe pattern jumps at vertex {v}: corner angles {a0:.6g} and {a:.6g}")


def check_vtk(data):
    lines = data.decode().splitlines()
    if len(lines) < 4 or not lines[0].startswith("# vtk DataFile") or lines[2].strip() != "ASCII" \
            or lines[3].split() != ["DATASET", "POLYDATA"]:
        raise Bad("no legacy ASCII POLYDATA header")
    tokens = " ".join(lines[4:]).split()
    at, nv, polygons = 0, None, 0

    def take(n, what):
        nonlocal at
        if at + n > len(tokens):
            raise Bad(f"{n} values of {what} announced, fewer given")
        values = tokens[at:at + n]
        at += n
        return values
    while at < len(tokens):
        key = tokens[at]
        if key == "POINTS":
            nv = int(tokens[at + 1])
            at += 3
            finite([float(x) for x in take(3 * nv, "POINTS")], "coordinate")
        elif key == "POLYGONS":
            polygons, size = int(tokens[at + 1]), int(tokens[at + 2])
            at += 3
            values = [int(x) for x in take(size, "POLYGONS")]
            faces, k = [], 0
            while k < len(values):
                faces.append(values[k + 1:k + 1 + values[k]])
                k += 1 + values[k]
            if k != size or len(faces) != polygons:
                raise Bad(f"{polygons} polygons announced, {len(faces)} given")
            check_faces(faces, nv or 0)
        elif key == "POINT_DATA":
            if int(tokens[at + 1]) != nv:
                raise Bad(f"POINT_DATA {tokens[at + 1]} for {nv} points")
            at += 2
        elif key == "SCALARS":
            at += 4 if tokens[at + 3] == "1" else 3
            if tokens[at] == "LOOKUP_TABLE":
                at += 2
            finite([float(x) for x in take(nv, "SCALARS")], "scalar")
        elif key == "NORMALS":
            at += 3
            finite([float(x) for x in take(3 * nv, "NORMALS")], "normal")
        else:
            raise Bad(f"unexpected {key!r}")
    if nv is None or polygons == 0:
        raise Bad("no points or no polygons")
    return nv, polygons


def check_svg(data):
    root = ET.fromstring(data)
    if not root.tag.endswith("svg"):
        raise Bad(f"the root element is <{root.tag}>, not <svg>")
    drawn = [e for e in root.iter() if e.tag.split("}")[-1] in ("path", "polygon", "polyline", "line", "circle", "rect")]
    if not drawn:
        raise Bad("nothing is drawn")
    return len(drawn), 0


def check_png(data):
    if not data.startswith(b"\x89PNG\r\n\x1a\n"):
        raise Bad("no PNG signature")
    at, chunks, size = 8, [], (0, 0)
    while at < len(data):
        (length,) = struct.unpack_from(">I", data, at)
        kind = data[at + 4:at + 8]
        content = data[at + 8:at + 8 + length]
        (crc,) = struct.unpack_from(">I", data, at + 8 + length)
        if zlib.crc32(kind + content) != crc:
            raise Bad(f"a wrong CRC in chunk {kind}")
        if kind == b"IHDR":
            size = struct.unpack_from(">II", content, 0)
        chunks.append(kind)
        at += 12 + length
    if not chunks or chunks[0] != b"IHDR" or chunks[-1] != b"IEND" or 0 in size:
        raise Bad("not a complete PNG (IHDR ... IEND of non-zero size)")
    return size


def check_pdf(data):
    """An uncompressed PDF with a classic cross-reference table: every offset at its object, every
    stream as long as its /Length, startxref at the table. Returns (pages, objects)."""
    if not data.startswith(b"%PDF-1."):
        raise Bad("no PDF header")
    tail = data.rstrip()
    if not tail.endswith(b"%%EOF"):
        raise Bad("no %%EOF at the end")
    start = data.rfind(b"startxref")
    xref = int(data[start + 9:].split()[0])
    if data[xref:xref + 4] != b"xref":
        raise Bad(f"startxref {xref} does not point at the cross-reference table")
    lines = data[xref:].split(b"\n")
    first, count = (int(x) for x in lines[1].split())
    if first != 0:
        raise Bad("the cross-reference table does not start at object 0")
    for i in range(1, count):
        offset = int(lines[2 + i][:10])
        if not data[offset:].startswith(b"%d 0 obj" % i):
            raise Bad(f"object {i} is not at its offset {offset}")
    at = 0
    while True:
        at = data.find(b"/Length ", at)
        if at < 0:
            break
        length = int(data[at + 8:].split()[0])
        begin = data.find(b"stream\n", at) + 7
        if data[begin + length:begin + length + 9] != b"endstream":
            raise Bad(f"a stream is not {length} bytes long")
        at = begin + length
    pages = data.count(b"/Type /Page ") + data.count(b"/Type /Page\n")
    if pages == 0:
        raise Bad("no page")
    return pages, count - 1


def check_text(data):
    data.decode()
    return 0, 0


def check(path):
    if not os.path.isfile(path):
        raise Bad("missing")
    data = open(path, "rb").read()
    if not data:
        raise Bad("empty")
    ext = os.path.splitext(path)[1].lower()
    checkers = {".off": check_off, ".obj": check_obj, ".ply": check_ply, ".svg": check_svg, ".pdf": check_pdf, ".png": check_png, ".vtk": check_vtk,
                ".txt": check_text, ".csv": check_text, ".json": lambda d: (json.loads(d), 0)}
    if ext not in checkers:
        raise Bad(f"no reader for {ext} files")
    try:
        return checkers[ext](data)
    except (ValueError, IndexError, struct.error, UnicodeDecodeError, ET.ParseError, StopIteration) as e:
        raise Bad(f"does not parse: {e}")


def self_test():
    """The checker is an oracle too: it must reject each of these broken files and accept the
    well-formed ones."""
    import tempfile
    png_chunk = lambda kind, content: struct.pack(">I", len(content)) + kind + content + \
        struct.pack(">I", zlib.crc32(kind + content))
    png = b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 2, 8, 2, 0, 0, 0)) + \
        png_chunk(b"IDAT", zlib.compress(b"\0" * 14)) + png_chunk(b"IEND", b"")
    ply_header = b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\nproperty double y\n" \
        b"property double z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
    ply_body = struct.pack("<9d", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<B3i", 3, 0, 1, 2)
    # two triangles sharing the edge 1-2; the second one's corner at vertex 2 is alpha + jump
    # (minus sign: the sheets of a line field), so any jump but 0 or pi breaks the pattern
    stripes_ply = lambda jump: ("ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
                                "property double z\nelement face 2\nproperty list uchar int vertex_indices\n"
                                "property list uchar float corner_alpha\nend_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n"
                                f"3 0 1 2 3 0.1 0.2 0.3\n3 2 1 3 3 {-0.3 + jump} -0.2 7\n"
                                ).encode()
    vtk = b"# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0\n1 0 0\n0 1 0\n" \
        b"POLYGONS 1 4\n3 0 1 2\nPOINT_DATA 3\nSCALARS z float 1\nLOOKUP_TABLE default\n0\n1\n2\n" \
        b"NORMALS normals float\n0 0 1\n0 0 1\n0 0 1\n"
    def pdf(shift=0, length_error=0):
        objects = [b"<< /Type /Catalog /Pages 2 0 R >>", b"<< /Type /Pages /Kids [3 0 R] /Count 1 >>",
                   b"<< /Type /Page /Parent 2 0 R /MediaBox [0 0 10 10] /Contents 4 0 R >>",
                   b"<< /Length %d >>\nstream\n0 0 m 1 1 l S\nendstream" % (14 + length_error)]
        out, offsets = b"%PDF-1.4\n", []
        for i, body in enumerate(objects, 1):
            offsets.append(len(out))
            out += b"%d 0 obj\n" % i + body + b"\nendobj\n"
        xref = len(out)
        out += b"xref\n0 5\n0000000000 65535 f \n" + b"".join(b"%010d 00000 n \n" % (o + shift) for o in offsets)
        return out + b"trailer\n<< /Size 5 /Root 1 0 R >>\nstartxref\n%d\n%%%%EOF\n" % xref
    good = {"a.off": b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
            "a.pdf": pdf(),
            "b.off": b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0 0\n",
            "a.obj": b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
            "lines.obj": b"v 0 0 0\nv 1 0 0\nv 0 1 0\ng level_0\nl 1 2 3 1\n",
            "a.ply": ply_header + ply_body,
            "b.ply": b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                     b"element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
            "a.svg": b"<svg xmlns='http://www.w3.org/2000/svg'><path d='M0 0L1 1'/></svg>",
            "stripes.ply": stripes_ply(0.0),
            "a.png": png,
            "a.vtk": vtk}
    bad = {"empty.off": b"",
           "truncated.off": b"OFF\n3 1 0\n0 0 0\n1 0 0\n",
           "nan.off": b"OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n",
           "range.off": b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
           "repeat.obj": b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2\n",
           "range_line.obj": b"v 0 0 0\nv 1 0 0\nl 1 3\n",
           "stutter_line.obj": b"v 0 0 0\nv 1 0 0\nl 1 2 2\n",
           "points.obj": b"v 0 0 0\nv 1 0 0\n",
           "short.ply": ply_header + ply_body[:-4],
           "jump.ply": stripes_ply(0.5),
           "long.ply": ply_header + ply_body + b"\0",
           "open.svg": b"<svg xmlns='http://www.w3.org/2000/svg'><path d='M0 0L1 1'/>",
           "blank.svg": b"<svg xmlns='http://www.w3.org/2000/svg'></svg>",
           "offset.pdf": pdf(shift=1),
           "length.pdf": pdf(length_error=2),
           "truncated.pdf": pdf()[:-20],
           "cut.png": png[:-12],
           "crc.png": png[:20] + bytes([png[20] ^ 1]) + png[21:],
           "range.vtk": vtk.replace(b"3 0 1 2", b"3 0 1 3"),
           "short.vtk": vtk[:-6],
           "nan.vtk": vtk.replace(b"1 0 0", b"nan 0 0"),
           "a.xyz": b"1 2 3\n"}
    failures = 0
    with tempfile.TemporaryDirectory() as folder:
        for files, should_pass in ((good, True), (bad, False)):
            for name, content in files.items():
                path = os.path.join(folder, name)
                with open(path, "wb") as f:
                    f.write(content)
                try:
                    check(path)
                    passed = True
                except Bad:
                    passed = False
                if passed != should_pass:
                    print(f"FAILED  {name} was {'accepted' if passed else 'rejected'}")
                    failures += 1
        if not check_missing(os.path.join(folder, "missing.off")):
            print("FAILED  a missing file was accepted")
            failures += 1
    total = len(good) + len(bad) + 1
    print(f"{total - failures} passed, {failures} failed")
    return 1 if failures else 0


def check_missing(path):
    try:
        check(path)
        return False
    except Bad:
        return True


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    bad = 0
    for path in sys.argv[1:]:
        try:
            check(path)
        except Bad as e:
            print(f"{path}: {e}")
            bad += 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
