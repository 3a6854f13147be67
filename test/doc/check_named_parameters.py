#!/usr/bin/env python3
# Copyright (c) 2026 The CGAL Surface Design authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks that the table of named parameters of the manual is complete and has no stray names:
every CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(name) of include/CGAL/Surface_design/parameters.h
must be listed in the first column of the table after "Every named parameter of the library:" in
doc/Surface_design/Surface_design.md, and every backquoted name of that column must be declared
there, unless its cell is marked "(CGAL)" (CGAL's own parameters). A missing table fails too.
usage: check_named_parameters.py PROJECT_ROOT  (exit 1 with one line per offender)
       check_named_parameters.py --self-test   (broken inputs must be rejected, a good one accepted)"""

import os
import re
import sys

HEADER = os.path.join("include", "CGAL", "Surface_design", "parameters.h")
MANUAL = os.path.join("doc", "Surface_design", "Surface_design.md")
MARKER = "Every named parameter of the library:"

DECLARATION = re.compile(r"^[ \t]*CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER\([ \t]*([A-Za-z_]\w*)[ \t]*\)", re.M)
BACKQUOTED_NAME = re.compile(r"`([A-Za-z_]\w*)`")


def declared_parameters(header_text):
    """The names of the CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(name) lines (not the #define)."""
    return DECLARATION.findall(header_text)


def split_row(line):
    """The cells of a Markdown table row; an escaped pipe (\\|) does not separate cells."""
    body = line.strip()
    if body.startswith("|"):
        body = body[1:]
    if body.endswith("|") and not body.endswith("\\|"):
        body = body[:-1]
    return [cell.strip() for cell in re.split(r"(?<!\\)\|", body)]


def table_names(manual_text):
    """(library names, CGAL names, problems) of the first column of the table that follows
    MARKER. The table must start after blank lines only, with a header row whose first cell is
    "named parameter" and a separator row; it ends at the first line that is not a row."""
    lines = manual_text.splitlines()
    start = next((i for i, line in enumerate(lines) if MARKER in line), None)
    if start is None:
        return [], [], [f'table not found: no line "{MARKER}" in the manual']
    i = start + 1
    while i < len(lines) and not lines[i].strip():
        i += 1
    if i + 1 >= len(lines) or not lines[i].lstrip().startswith("|") or \
            split_row(lines[i])[0].lower() != "named parameter" or \
            not re.fullmatch(r"\|?(\s*:?-+:?\s*\|)+\s*:?-*:?\s*", lines[i + 1].strip()):
        return [], [], [f'table not found: "{MARKER}" (line {start + 1}) is not followed by a table whose '
                        f'header starts with "| named parameter |" and a separator row']
    library, cgal, problems = [], [], []
    i += 2
    while i < len(lines) and lines[i].lstrip().startswith("|"):
        first = split_row(lines[i])[0]
        names = BACKQUOTED_NAME.findall(first)
        if not names:
            problems.append(f"line {i + 1}: a row of the table names no parameter in its first column: {first!r}")
        (cgal if "(CGAL)" in first else library).extend(names)
        i += 1
    if not library and not cgal and not problems:
        problems.append(f'table not found: the table after "{MARKER}" (line {start + 1}) has no rows')
    return library, cgal, problems


def check(header_text, manual_text):
    """The problems (an empty list when the table matches the declarations)."""
    declared = declared_parameters(header_text)
    problems = []
    if not declared:
        problems.append(f"no CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(name) found in {HEADER}")
    library, cgal, table_problems = table_names(manual_text)
    problems += table_problems
    if any(p.startswith("table not found") for p in table_problems):
        return problems
    listed = set(library)
    for name in declared:
        if name in set(cgal):
            problems.append(f"{name}: declared in {HEADER} but marked \"(CGAL)\" in the table of {MANUAL}")
        elif name not in listed:
            problems.append(f"{name}: declared in {HEADER} but missing from the table of {MANUAL}")
    declared_set = set(declared)
    for name in dict.fromkeys(library):  # in table order, once each
        if name not in declared_set:
            problems.append(f"{name}: in the table of {MANUAL} but not declared in {HEADER} "
                            f"(mark it \"(CGAL)\" if it is one of CGAL's parameters)")
    return problems


def self_test():
    """The checker must reject each broken input, naming the offender, and accept the good one."""
    header = ("#define CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(NAME) \\\n  template <typename K> ...\n"
              "CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(alpha)\n"
              "CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER(beta)\n"
              "  CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER( gamma )\n"
              "#undef CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER\n")
    head = ("Some text.\n\n" + MARKER + "\n\n"
            "| named parameter | type and range | default | read by |\n"
            "|---|---|---|---|\n"
            "| `vertex_point_map` (CGAL) | a map | `get(CGAL::vertex_point, tm)` | all |\n"
            "| `vertex_index_map`, `face_index_map` (CGAL) | maps onto `[0, n)` | the mesh's own | all |\n")
    tail = "\nCGAL's tags live in `CGAL::internal_np`; `not_a_parameter` is outside the table.\n"
    good = head + ("| `alpha` | `double` \\| `int` in `[0, 1]` | 0 | `f` |\n"
                   "| `beta`, `gamma` | `bool` | `true`, `false` | `g` |\n") + tail
    cases = [
        ("a correct table", header, good, None),
        ("a library parameter marked as CGAL's", header,
         head + "| `alpha` | `double` | 0 | `f` |\n| `beta`, `gamma` (CGAL) | `bool` | `true` | `g` |\n" + tail, "beta"),
        ("a library parameter missing from the table", header,
         head + "| `alpha` | `double` | 0 | `f` |\n| `beta` | `bool` | `true` | `g` |\n" + tail, "gamma"),
        ("a name in the table that is not declared", header,
         good.replace("| `alpha` |", "| `alpha`, `delta` |"), "delta"),
        ("an undeclared name in a row of its own", header,
         good.replace(tail, "| `epsilon` | `int` | 1 | `h` |\n" + tail), "epsilon"),
        ("no table (no introducing line)", header, good.replace(MARKER, "Some named parameters:"),
         "table not found"),
        ("no table after the introducing line", header, "Text.\n\n" + MARKER + "\n\nNo table here.\n",
         "table not found"),
        ("a header without declarations", "// nothing\n", good, "no CGAL_SURFACE_DESIGN_ADD_NAMED_PARAMETER"),
    ]
    failures = 0
    for what, header_text, manual_text, offender in cases:
        problems = check(header_text, manual_text)
        if offender is None:
            ok = not problems
        else:
            ok = any(offender in p for p in problems)
        print(f"{'ok  ' if ok else 'FAIL'} {what}: " +
              ("accepted" if not problems else "rejected: " + "; ".join(problems)))
        failures += not ok
    if failures:
        print(f"self-test: {failures} of {len(cases)} cases misjudged")
        return 1
    print(f"self-test: all {len(cases)} cases judged correctly")
    return 0


def main(argv):
    if argv == ["--self-test"]:
        return self_test()
    if len(argv) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    root = argv[0]
    texts = []
    for relative in (HEADER, MANUAL):
        path = os.path.join(root, relative)
        try:
            with open(path, encoding="utf-8") as f:
                texts.append(f.read())
        except OSError as e:
            print(f"cannot read {path}: {e}")
            return 1
    problems = check(*texts)
    for p in problems:
        print(p)
    if problems:
        print(f"{len(problems)} problem(s) with the table of named parameters of {MANUAL}")
        return 1
    library, cgal, _ = table_names(texts[1])
    print(f"all {len(declared_parameters(texts[0]))} library parameters of {HEADER} are in the table of {MANUAL} "
          f"({len(set(library))} library names, {len(set(cgal))} of CGAL)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
