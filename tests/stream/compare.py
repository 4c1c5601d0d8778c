#!/usr/bin/env python3
"""Compiling in a stream gives the module and diagnostics of compiling the whole IR (issue 6).

For every golden case of a dialect that names a source program, `ncc compile` (with
the case's options) runs with and without --no-stream: exit status, diagnostics and
the bytes of the .ncb must be identical; so must `ncc check` (its report includes the
dry run). Then a generated program: plain blocks (what the stream takes; one with a
word twice, an error its checks find) followed by the near-plain and damaged blocks of
tests/fastpath, compared the same way with no error limit and with a limit of 5.

usage: compare.py NCC GOLDEN_DIR DIALECT [--blocks N] [--seed S]
"""
import os
import random
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "fastpath"))
from compare import golden_cases, print_first_difference, random_block  # noqa: E402


def run_both(ncc, args, cwd, tmp):
    """(exit, stdout, stderr, .ncb bytes) of compile and of check, streamed and not."""
    results = []
    for extra in ([], ["--no-stream"]):
        ncb = os.path.join(tmp, "out.ncb")
        if os.path.exists(ncb):
            os.unlink(ncb)
        c = subprocess.run([ncc, "compile"] + extra + args + ["-o", ncb], cwd=cwd, capture_output=True, text=True)
        data = open(ncb, "rb").read() if os.path.exists(ncb) else b""
        k = subprocess.run([ncc, "check"] + extra + args, cwd=cwd, capture_output=True, text=True)
        results.append(((c.returncode, c.stdout, c.stderr, data), (k.returncode, k.stdout, k.stderr)))
    return results


def differs(name, results):
    (stream, whole) = results
    if stream == whole:
        return False
    for what, a, b in (("compile", stream[0], whole[0]), ("check", stream[1], whole[1])):
        if a == b:
            continue
        print(f"DIFFER {name}: ncc {what}: exit {a[0]} vs {b[0]}")
        if len(a) > 3 and a[3] != b[3]:
            print(f"  the .ncb files differ ({len(a[3])} and {len(b[3])} bytes)")
        print_first_difference(a[1] + a[2], b[1] + b[2], "stream", "whole")
    return True


def plain_block(rng, dialect, k):
    move = f"G1 X{rng.uniform(-99, 99):.3f} Y{rng.uniform(-99, 99):.3f} Z{rng.uniform(-9, 0):.3f} F{rng.choice([500, 800, 1200])}"
    return {"gost": f"N{k % 10000:04d} ", "pp": f"N{k + 1} "}.get(dialect, "") + move


def main():
    ncc, golden_dir, dialect = sys.argv[1], sys.argv[2], sys.argv[3]
    blocks = int(sys.argv[sys.argv.index("--blocks") + 1]) if "--blocks" in sys.argv else 2000
    seed = int(sys.argv[sys.argv.index("--seed") + 1]) if "--seed" in sys.argv else 1
    failures = cases = 0
    with tempfile.TemporaryDirectory() as tmp:
        for name, args in golden_cases(golden_dir):
            cases += 1
            failures += differs(name, run_both(ncc, args, golden_dir, tmp))
        # Generated: plain blocks the stream takes, then blocks that stop it.
        rng = random.Random(seed)
        header = {"iso": "", "gost": "%\n", "pp": "%1\n", "nc110": "G17\n"}[dialect]
        clean = [plain_block(rng, dialect, k + 1) for k in range(blocks // 2)]
        # A word twice: an error the checks find in a block the stream has taken.
        clean[len(clean) // 2] += " X1"
        mixed = [random_block(rng, dialect) for _ in range(blocks - blocks // 2)]
        if dialect == "pp":
            mixed = [f"N{len(clean) + k + 1} " + l.replace("N", "") for k, l in enumerate(mixed)]
        corpus = os.path.join(tmp, "corpus.nc")
        with open(corpus, "w", encoding="utf-8") as f:
            f.write(header + "\n".join(clean + mixed) + "\nM30\n")
        # With no error limit, and with one the reader's errors reach after the stream's.
        for limit in ("0", "5"):
            failures += differs(f"generated program ({blocks} blocks, seed {seed}, error limit {limit})",
                                run_both(ncc, [corpus, "--dialect", dialect, "--error-limit", limit], golden_dir, tmp))
    print(f"{cases} golden cases and a generated program of {blocks} blocks: {failures} differ")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
