#!/usr/bin/env python3
"""Assembles the seed corpora of the fuzz targets (docs/limits.md, "Fuzzing").

    corpus.py OUT [--ncc NCC]

OUT/<target>/ receives, for each front end (iso, gost, pp, nc110), the programs the
golden cases of tests/golden read in that dialect (the file each command names and
the programs of the library it gives with --lib) and the real programs of
seeds/realworld; for fastpath, each of those with its dialect's byte first (the
target's first byte picks the dialect); for bytecode, the bytecode files the golden
cases read and, given NCC, every golden program that compiles, compiled (the files
are made here, not kept: the format has a version). A file's name says where it
comes from; a content already there is not written twice.
"""
import argparse
import concurrent.futures
import hashlib
import os
import pathlib
import shlex
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
GOLDEN = HERE.parent / "golden"
REALWORLD = HERE / "seeds" / "realworld"
DIALECTS = ["iso", "gost", "pp", "nc110"]  # fastpath.cpp's order: the first byte picks one
VALUE_OPTIONS = {"--dialect", "--machine", "--lib", "--process", "--diagnostics-format", "--error-limit",
                 "--color", "-o", "--trace", "--trace-format", "--max-steps", "--start-block", "--files",
                 "--input"}
COMPILE_SECONDS = 20  # a program whose dry run loops is not a seed worth waiting for


class Corpus:
    def __init__(self, root):
        self.root = root
        self.seen = {}

    def add(self, target, name, data):
        digest = hashlib.sha1(data).hexdigest()
        if digest in self.seen.setdefault(target, set()):
            return
        self.seen[target].add(digest)
        folder = self.root / target
        folder.mkdir(parents=True, exist_ok=True)
        (folder / name).write_bytes(data)


def golden_inputs():
    """(dialect, path) of every file a golden case reads as a program or a bytecode file."""
    found = set()
    for case in sorted(GOLDEN.glob("*/*.out")):
        words = shlex.split(case.read_text(errors="replace").splitlines()[0])[2:]  # "$ ncc ARGS"
        if not words or words[0] not in ("check", "compile", "run", "disasm", "ir"):
            continue
        dialect, files = "gost", []
        args = iter(words[1:])
        for arg in args:
            if arg in VALUE_OPTIONS:
                value = next(args, "")
                if arg == "--dialect":
                    dialect = value
                elif arg == "--lib":
                    files += [p for p in sorted((case.parent / value).rglob("*")) if p.is_file()]
            elif not arg.startswith("-") and "@" not in arg:  # @GEN@: made at test time, too large
                files.append(case.parent / arg)
        found.update((dialect, f) for f in files if f.is_file())
    return sorted(found)


def seed_name(path, base):
    return str(path.relative_to(base)).replace("/", "_")


def compile_seed(ncc, dialect, source, out):
    try:
        subprocess.run([ncc, "compile", "--dialect", dialect, str(source), "-o", str(out)], cwd=source.parent,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=COMPILE_SECONDS)
    except subprocess.TimeoutExpired:
        pass
    return out if out.is_file() else None


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out", type=pathlib.Path)
    parser.add_argument("--ncc", help="compiles the golden programs into bytecode seeds")
    options = parser.parse_args()
    options.out = options.out.resolve()
    corpus = Corpus(options.out)
    programs = []  # (dialect, path) of the golden programs
    for dialect, path in golden_inputs():
        data = path.read_bytes()
        name = seed_name(path, GOLDEN)
        if data.startswith(b"NCCB"):
            corpus.add("bytecode", name, data)
        elif dialect in DIALECTS:
            programs.append((dialect, path))
            corpus.add(dialect, name, data)
            corpus.add("fastpath", f"{dialect}_{name}", bytes([DIALECTS.index(dialect)]) + data)
    for path in sorted(p for p in REALWORLD.rglob("*") if p.is_file()):
        data = path.read_bytes()
        for dialect in DIALECTS:
            corpus.add(dialect, "realworld_" + seed_name(path, REALWORLD), data)
            corpus.add("fastpath", f"{dialect}_realworld_{seed_name(path, REALWORLD)}",
                       bytes([DIALECTS.index(dialect)]) + data)
    if options.ncc:
        with tempfile.TemporaryDirectory() as work, concurrent.futures.ThreadPoolExecutor(os.cpu_count() or 1) as pool:
            jobs = [pool.submit(compile_seed, os.path.abspath(options.ncc), dialect, path,
                                pathlib.Path(work) / f"{dialect}_{seed_name(path, GOLDEN)}.ncb")
                    for dialect, path in programs]
            for job in jobs:
                if out := job.result():
                    corpus.add("bytecode", out.name, out.read_bytes())
    for target in sorted(corpus.seen):
        print(f"{target}: {len(corpus.seen[target])} seeds")


if __name__ == "__main__":
    sys.exit(main())
