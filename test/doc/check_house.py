#!/usr/bin/env python3
# Copyright (c) 2026 The CGAL Surface Design authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks the rules of the library's layout (doc/Surface_design/Surface_design.md, section 2):

1. the solver wing (internal/Solvers/) includes nothing of the library but itself and exceptions.h;
2. the mesh core (internal/Core/) includes only itself, the wing and the leaf public type headers
   (exceptions.h, parameters.h, edge_weighting.h, developability_energy.h);
3. a package's folder internal/<Package>/ includes only itself, the core, the wing and those type
   headers: never another package's folder nor a public algorithm header;
4. no installed header (include/CGAL/Surface_design/**.h) exceeds 1000 lines;
5. the programs and the manuals' examples (every .cpp and .h under examples/) use public headers
   only: no include under CGAL/Surface_design/internal/ and no name qualified with internal::;
6. no test name of test/*.cpp holds a ';': CTest's discovery splits the name there and registers
   halves that match no test, which then fail.
Comments are ignored.

Usage: check_house.py PROJECT_ROOT      (exit 1 naming each offending line)
       check_house.py --self-test       (each rule on a small tree made to break it, and a good one)
"""
import os
import re
import sys
import tempfile

INCLUDE = re.compile(r'#\s*include\s*[<"]CGAL/Surface_design/([^>"]+)[>"]')
QUOTED = re.compile(r'#\s*include\s*"([^"]+)"')
TEST_NAME = re.compile(r'\b(?:TEMPLATE_)?TEST_CASE\s*\(\s*"((?:[^"\\]|\\.)*)"')
QUALIFIED = re.compile(r'\binternal::|namespace\s+\w+\s*=\s*[\w:]*\binternal\b|using\s+namespace\s+[\w:]*\binternal\b')
TYPE_HEADERS = {"exceptions.h", "parameters.h", "edge_weighting.h", "developability_energy.h"}
MAX_LINES = 1000


def code_lines(path):
    """(line number, code without comments, original line) of a C++ file."""
    in_block = False
    with open(path, encoding="utf-8", errors="replace") as f:
        for number, line in enumerate(f, 1):
            out, i = "", 0
            while i < len(line):
                if in_block:
                    end = line.find("*/", i)
                    if end < 0:
                        i = len(line)
                        continue
                    i, in_block = end + 2, False
                elif line.startswith("//", i):
                    break
                elif line.startswith("/*", i):
                    in_block, i = True, i + 2
                else:
                    out += line[i]
                    i += 1
            yield number, out, line.rstrip("\n")


def files(folder, extensions):
    for here, _, names in os.walk(folder):
        for name in sorted(names):
            if name.endswith(extensions):
                yield os.path.join(here, name)


def allowed_include(folder, target):
    """Whether a header of internal/<folder>/ may include CGAL/Surface_design/<target>."""
    if folder == "Solvers":
        return target.startswith("internal/Solvers/") or target == "exceptions.h"
    if target in TYPE_HEADERS or target.startswith(("internal/Solvers/", "internal/Core/")):
        return True
    return target.startswith("internal/%s/" % folder)


def included(path, code, headers):
    """The header of the library that the line `code` of `path` includes (its path under
    CGAL/Surface_design/), whether written <CGAL/Surface_design/...> or as a quoted relative path;
    None for any other line or header."""
    m = INCLUDE.search(code)
    if m:
        return m.group(1)
    m = QUOTED.search(code)
    if m:
        target = os.path.normpath(os.path.join(os.path.dirname(path), m.group(1)))
        if os.path.commonpath([target, headers]) == headers:
            return os.path.relpath(target, headers).replace(os.sep, "/")
    return None


def offenders(root):
    found = []
    headers = os.path.normpath(os.path.join(root, "include", "CGAL", "Surface_design"))
    for path in files(headers, (".h",)):
        rel = os.path.relpath(path, root)
        parts = os.path.relpath(path, headers).split(os.sep)
        if len(parts) == 2 and parts[0] == "internal":
            found.append("%s: a header directly in internal/ belongs to no folder" % rel)
        lines = 0
        for number, code, line in code_lines(path):
            lines = number
            target = included(path, code, headers)
            if target and len(parts) >= 3 and parts[0] == "internal" and not allowed_include(parts[1], target):
                found.append("%s:%d: internal/%s/ may not include %s" % (rel, number, parts[1], target))
        if lines > MAX_LINES:
            found.append("%s: %d lines, more than %d" % (rel, lines, MAX_LINES))
    for path in files(os.path.join(root, "examples"), (".cpp", ".h")):
        for number, code, line in code_lines(path):
            target = included(path, code, headers)
            if (target and target.startswith("internal/")) or QUALIFIED.search(code):
                found.append("%s:%d: uses the library's internals: %s" % (os.path.relpath(path, root), number, line.strip()))
    for path in files(os.path.join(root, "test"), (".cpp",)):
        for number, code, line in code_lines(path):
            m = TEST_NAME.search(code)
            if m and ";" in m.group(1):
                found.append("%s:%d: a test name with ';' (CTest splits it there): %s"
                             % (os.path.relpath(path, root), number, m.group(1)))
    return found


def self_test():
    good = {"include/CGAL/Surface_design/internal/Solvers/a.h": "#include <CGAL/Surface_design/exceptions.h>\n",
            "include/CGAL/Surface_design/internal/Core/b.h": "#include <CGAL/Surface_design/internal/Solvers/a.h>\n"
                                                             "#include <CGAL/Surface_design/edge_weighting.h>\n",
            "include/CGAL/Surface_design/internal/Pkg/c.h": "#include <CGAL/Surface_design/internal/Core/b.h>\n"
                                                            "#include <CGAL/Surface_design/internal/Pkg/d.h>\n",
            "include/CGAL/Surface_design/algorithm.h": "#include <CGAL/Surface_design/internal/Pkg/c.h>\n",
            "examples/Programs/p.cpp": "#include <CGAL/Surface_design/algorithm.h>\nint x; // internal:: here is a comment\n"
                                       "/* internal::g()\n   still internal:: */ int y;\n",
            "test/t.cpp": 'TEMPLATE_TEST_CASE("a name, with commas: and colons", "[t]", int) {}\n'}
    cases = [("a good tree", {}, False),
             ("the wing includes the core", {"include/CGAL/Surface_design/internal/Solvers/a.h":
                                             "#include <CGAL/Surface_design/internal/Core/b.h>\n"}, True),
             ("the wing includes a public type header", {"include/CGAL/Surface_design/internal/Solvers/a.h":
                                                         "#include <CGAL/Surface_design/parameters.h>\n"}, True),
             ("the core includes a package", {"include/CGAL/Surface_design/internal/Core/b.h":
                                              "#include <CGAL/Surface_design/internal/Pkg/c.h>\n"}, True),
             ("a package includes another", {"include/CGAL/Surface_design/internal/Pkg/c.h":
                                             "#include <CGAL/Surface_design/internal/Other/e.h>\n"}, True),
             ("a package includes a public algorithm header", {"include/CGAL/Surface_design/internal/Pkg/c.h":
                                                               "#include <CGAL/Surface_design/algorithm.h>\n"}, True),
             ("a header of 1001 lines", {"include/CGAL/Surface_design/algorithm.h": "int x;\n" * 1001}, True),
             ("a program uses internal::", {"examples/Programs/p.cpp": "int f() { return CGAL::Surface_design::internal::g(); }\n"}, True),
             ("an example includes an internal header", {"examples/Pkg/e.cpp": "#include <CGAL/Surface_design/internal/Core/b.h>\n"}, True),
             ("a package includes another by a quoted path", {"include/CGAL/Surface_design/internal/Pkg/c.h":
                                                              '#include "../Other/e.h"\n'}, True),
             ("the wing includes the core from a subfolder", {"include/CGAL/Surface_design/internal/Solvers/sub/f.h":
                                                              "#include <CGAL/Surface_design/internal/Core/b.h>\n"}, True),
             ("a header directly in internal/", {"include/CGAL/Surface_design/internal/loose.h": "int x;\n"}, True),
             ("an example aliases the internal namespace", {"examples/Pkg/e.cpp":
                                                            "namespace SDI = CGAL::Surface_design::internal;\n"}, True),
             ("an example uses the internal namespace", {"examples/Pkg/e.cpp":
                                                         "using namespace CGAL::Surface_design::internal;\n"}, True),
             ("an example includes an internal header by a quoted path", {"examples/Pkg/e.cpp":
                                                                          '#include "../../include/CGAL/Surface_design/internal/Core/b.h"\n'}, True),
             ("a test name with a semicolon", {"test/t.cpp": 'TEST_CASE("constant; varying", "[t]") {}\n'}, True)]
    ok = True
    for title, change, bad in cases:
        tree = dict(good)
        tree.update(change)
        with tempfile.TemporaryDirectory() as root:
            for rel, text in tree.items():
                path = os.path.join(root, rel)
                os.makedirs(os.path.dirname(path), exist_ok=True)
                with open(path, "w") as f:
                    f.write(text)
            judged = offenders(root)
        print("%s %s: %s" % ("ok  " if bool(judged) == bad else "FAIL", title, "; ".join(judged) or "accepted"))
        ok = ok and bool(judged) == bad
    return 0 if ok else 1


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    if sys.argv[1] == "--self-test":
        return self_test()
    found = offenders(sys.argv[1])
    for line in found:
        print(line)
    if not found:
        print("the layout holds: the wing and the core include nothing above them, no package includes another, "
              "no header exceeds %d lines, examples/ uses public headers only, no test name holds ';'" % MAX_LINES)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
