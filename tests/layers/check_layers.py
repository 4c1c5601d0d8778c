#!/usr/bin/env python3
"""Fails on an #include or a link that crosses the layers of docs/layers.md.

    check_layers.py [ROOT]      check the tree at ROOT (the repository by default)
    check_layers.py --self-test check the checker on small trees of its own

The table in docs/layers.md says, for each folder, the folders its files may include
and the library it builds. A file belongs to the longest folder of the table its path
starts with, and so does the file an include names. Reported, each as file:line or
docs/layers.md: an include of a folder the table does not allow, an include that
names no file, a folder with sources and no row, a folder a row allows that no file
includes (the table must say what the code does, no more), a cycle in the table, and
a library that links another folder's library than those its row allows, or not all
of them.
"""
import fnmatch
import os
import re
import sys
import tempfile

TABLE = "docs/layers.md"
SOURCES = (".h", ".cpp", ".def")
# Where a quoted include is looked for after the including file's own folder: the
# include directories of the build (support/ adds the root, compiler/ and api/ theirs).
INCLUDE_DIRS = ("", "compiler", "include")
ANY = "anything"  # a row that may include every folder: the tests on top
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def read_table(root):
    """{folder: set of folders it may include, or None for anything}, {library: folder},
    and errors."""
    rows, libraries, errors = {}, {}, []
    lines = open(os.path.join(root, TABLE), encoding="utf-8").read().splitlines()
    start = next((i for i, l in enumerate(lines) if re.match(r"\|\s*folder\s*\|\s*may include\s*\|\s*library\s*\|", l)), None)
    if start is None:
        return rows, libraries, [f"{TABLE}: no table with the header | folder | may include | library |"]
    for n, line in enumerate(lines[start + 2:], start + 3):
        if not line.startswith("|"):
            break
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) != 3:
            errors.append(f"{TABLE}:{n}: a row has three cells: the folder, what it may include, its library")
            continue
        folder = cells[0].strip("`")
        if folder in rows:
            errors.append(f"{TABLE}:{n}: {folder} has two rows")
        allowed = re.findall(r"`([^`]+)`", cells[1])
        rows[folder] = None if allowed == [ANY] else set(allowed)
        for library in re.findall(r"`([^`]+)`", cells[2]):
            libraries[library] = folder
    for folder, allowed in rows.items():
        for other in sorted(allowed or ()):
            if other not in rows:
                errors.append(f"{TABLE}: {folder} may include {other}, which has no row")
    return rows, libraries, errors


def owner(path, rows):
    """The longest folder of the table that holds `path` (relative, '/'-separated)."""
    best = None
    for folder in rows:
        if (path == folder or path.startswith(folder + "/")) and (best is None or len(folder) > len(best)):
            best = folder
    return best


def source_files(root):
    for d, dirs, files in os.walk(root):
        # Not build trees (they hold generated sources), not .git and its kin.
        dirs[:] = sorted(x for x in dirs if not x.startswith(".") and not os.path.exists(os.path.join(d, x, "CMakeCache.txt")))
        for f in sorted(files):
            if f.endswith(SOURCES):
                yield os.path.relpath(os.path.join(d, f), root).replace(os.sep, "/")


def generated_headers(root):
    """The headers ANTLR makes of grammar/*.g4 (GostParser.h, GostParserBaseVisitor.h...)."""
    grammar = os.path.join(root, "grammar")
    stems = [f[:-3] for f in os.listdir(grammar) if f.endswith(".g4")] if os.path.isdir(grammar) else []
    return lambda name: "grammar" if any(re.fullmatch(re.escape(s) + r"(Base)?(Visitor|Listener)?\.h", name) for s in stems) else None


def resolve(root, path, name):
    """The file an include names, as the compiler finds it, or None."""
    for base in [os.path.dirname(path)] + list(INCLUDE_DIRS):
        candidate = os.path.normpath(os.path.join(base, name)).replace(os.sep, "/")
        if not candidate.startswith("..") and os.path.isfile(os.path.join(root, candidate)):
            return candidate
    return None


def links(root):
    """{target: [(file, line, library it links)]} from every CMakeLists.txt."""
    found = {}
    for d, dirs, files in os.walk(root):
        dirs[:] = sorted(x for x in dirs if not x.startswith(".") and not os.path.exists(os.path.join(d, x, "CMakeCache.txt")))
        if "CMakeLists.txt" not in files:
            continue
        path = os.path.relpath(os.path.join(d, "CMakeLists.txt"), root).replace(os.sep, "/")
        text = re.sub(r"#[^\n]*", "", open(os.path.join(root, path), encoding="utf-8").read())
        for m in re.finditer(r"target_link_libraries\s*\(([^)]*)\)", text):
            words = [(w.group(), text.count("\n", 0, m.start(1) + w.start()) + 1) for w in re.finditer(r"\S+", m.group(1))]
            found.setdefault(words[0][0], []).extend((path, line, dep) for dep, line in words[1:])
    return found


def check_links(root, rows, libraries):
    """A library of the table links the libraries of the folders its row allows, all of them."""
    errors = []
    targets = links(root)

    def folder_of(library):
        return next((f for pattern, f in libraries.items() if fnmatch.fnmatchcase(library, pattern)), None)

    def expand(dep, seen):
        """The libraries of the table a link brings: itself, or those of a target that gathers them."""
        if folder_of(dep) is not None:
            return [dep]
        seen.add(dep)
        return [lib for _, _, d in targets.get(dep, []) if d not in seen for lib in expand(d, seen)]

    for library, folder in sorted(libraries.items()):
        allowed = rows[folder]
        if allowed is None or "*" in library:
            continue
        linked = set()
        for path, line, dep in targets.get(library, []):
            for lib in expand(dep, {library}):
                there = folder_of(lib)
                if there == folder:
                    continue
                linked.add(there)
                if there not in allowed:
                    via = "" if lib == dep else f" (through {dep})"
                    errors.append(f"{path}:{line}: {library} links {lib}{via}: {folder} may not include {there} ({TABLE})")
        for other in sorted(allowed - linked):
            names = ", ".join(lib for lib, f in libraries.items() if f == other)
            if names:
                errors.append(f"{TABLE}: {folder} includes {other} but {library} does not link {names}")
    return errors


def cycle(rows):
    """A cycle of the table as a list of folders, or None."""
    state = {}

    def visit(folder, trail):
        state[folder] = "open"
        for other in sorted(rows.get(folder) or ()):
            if state.get(other) == "open":
                return trail[trail.index(other):] + [other]
            if other not in state and (found := visit(other, trail + [other])):
                return found
        state[folder] = "done"
        return None

    for folder in sorted(rows):
        if folder not in state and (found := visit(folder, [folder])):
            return found
    return None


def check(root):
    """Every problem of the tree at `root`, as lines to print."""
    rows, libraries, errors = read_table(root)
    if not rows:
        return errors
    if (found := cycle(rows)):
        errors.append(f"{TABLE}: the layers make a cycle: {' -> '.join(found)}")
    grammar_header = generated_headers(root)
    used = set()
    unowned = set()
    for path in source_files(root):
        here = owner(path, rows)
        if here is None:
            unowned.add(os.path.dirname(path) or ".")
            continue
        for n, line in enumerate(open(os.path.join(root, path), encoding="utf-8", errors="replace"), 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            name = m.group(1)
            target = resolve(root, path, name)
            there = owner(target, rows) if target else grammar_header(os.path.basename(name))
            if there is None:
                what = "names no file" if target is None else f"is in {os.path.dirname(target)}, which has no row"
                errors.append(f'{path}:{n}: #include "{name}" {what} ({TABLE})')
                continue
            if there == here:
                continue
            used.add((here, there))
            if rows[here] is not None and there not in rows[here]:
                allowed = ", ".join(sorted(rows[here])) or "nothing"
                errors.append(f'{path}:{n}: #include "{name}": {here} may not include {there} '
                              f"({TABLE}: {here} may include {allowed})")
    for folder in sorted(unowned):
        errors.append(f"{folder}: sources in a folder with no row in {TABLE}")
    for folder, allowed in sorted(rows.items()):
        for other in sorted(allowed or ()):
            if (folder, other) not in used:
                errors.append(f"{TABLE}: {folder} may include {other}, but no file of it does: drop it")
    return errors + check_links(root, rows, libraries)


# ---- The self-test: small trees, each with what the check must say of it ----------

SELF_TABLE = """# Layers

| folder | may include | library |
|---|---|---|
| `base` | | `lib_base` |
| `mid` | `base` | `lib_mid` |
| `top` | `mid`, `base` | `lib_top` |
| `tests` | `anything` | |
"""
GOOD = {
    "base/CMakeLists.txt": "add_library(lib_base a.cpp)\ntarget_link_libraries(lib_base PUBLIC fmt::fmt)\n",
    "mid/CMakeLists.txt": "target_link_libraries(lib_mid PUBLIC lib_base)\n",
    "top/CMakeLists.txt": "target_link_libraries(lib_top PRIVATE\n  lib_mid  # and lib_tests\n  lib_base)\n",
    "base/a.h": "#pragma once\n",
    "base/a.cpp": '#include "a.h"\n#include <vector>\n',
    "mid/b.h": '#include "base/a.h"\n',
    "top/c.cpp": '#include "mid/b.h"\n#include "base/a.h"\n',
    "tests/t.cpp": '#include "top/../mid/b.h"\n',
}
CASES = [
    ("a good tree", {}, SELF_TABLE, []),
    ("an include upwards", {"mid/d.cpp": '#include "top/c.cpp"\n'}, SELF_TABLE,
     ['mid/d.cpp:1: #include "top/c.cpp": mid may not include top']),
    ("an include past a layer", {}, SELF_TABLE.replace("| `top` | `mid`, `base` |", "| `top` | `mid` |"),
     ['top/c.cpp:2: #include "base/a.h": top may not include base',
      "top/CMakeLists.txt:3: lib_top links lib_base: top may not include base"]),
    ("an include of nothing", {"mid/f.cpp": '#include "base/gone.h"\n'}, SELF_TABLE,
     ['mid/f.cpp:1: #include "base/gone.h" names no file']),
    ("a folder with no row", {"extra/g.cpp": "int g;\n"}, SELF_TABLE, ["extra: sources in a folder with no row"]),
    ("an allowance no file uses", {}, SELF_TABLE.replace("| `mid` | `base` |", "| `mid` | `base`, `tests` |"),
     ["mid may include tests, but no file of it does"]),
    ("a link upwards", {"base/CMakeLists.txt": "\ntarget_link_libraries(lib_base PUBLIC lib_mid)\n"}, SELF_TABLE,
     ["base/CMakeLists.txt:2: lib_base links lib_mid: base may not include mid"]),
    ("a link through a library that gathers others",
     {"mid/CMakeLists.txt": "add_library(lib_all INTERFACE)\ntarget_link_libraries(lib_all INTERFACE lib_top lib_base)\n"
                            "target_link_libraries(lib_mid PUBLIC lib_all)\n"}, SELF_TABLE,
     ["mid/CMakeLists.txt:3: lib_mid links lib_top (through lib_all): mid may not include top"]),
    ("a link missing", {"top/CMakeLists.txt": "target_link_libraries(lib_top PUBLIC lib_mid)\n"}, SELF_TABLE,
     ["top includes base but lib_top does not link lib_base"]),
    ("a cycle", {"base/h.cpp": '#include "mid/b.h"\n'}, SELF_TABLE.replace("| `base` | |", "| `base` | `mid` |"),
     ["the layers make a cycle: base -> mid -> base", "base includes mid but lib_base does not link lib_mid"]),
]


def self_test():
    failures = 0
    for title, extra, table, expected in CASES:
        with tempfile.TemporaryDirectory() as root:
            for path, text in {**GOOD, **extra, TABLE: table}.items():
                os.makedirs(os.path.join(root, os.path.dirname(path)), exist_ok=True)
                with open(os.path.join(root, path), "w", encoding="utf-8") as f:
                    f.write(text)
            errors = check(root)
        missing = [e for e in expected if not any(e in line for line in errors)]
        unexpected = [line for line in errors if not any(e in line for e in expected)]
        if missing or unexpected:
            failures += 1
            print(f"FAIL {title}:\n  said: {errors}\n  missing: {missing}\n  unexpected: {unexpected}")
    print(f"{len(CASES) - failures} of {len(CASES)} cases as expected")
    return 1 if failures else 0


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    root = argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    errors = check(os.path.abspath(root))
    for e in errors:
        print(e)
    print(f"{len(errors)} layer problem{'' if len(errors) == 1 else 's'} ({TABLE})")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
