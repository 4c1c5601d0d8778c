#!/usr/bin/env python3
"""The fast path and the ANTLR parser give the same IR (issue 6, DESIGN.md decision 1).

For every golden case of a dialect, `ncc ir` with the case's options runs twice, with
and without --no-fast-path; the outputs (IR, diagnostics, exit status) must be
identical. Then a generated corpus: deterministic random blocks of address words with
the dialect's blanks, signs and decimal points, mixed with blocks only the parser
reads, compared the same way.

usage: compare.py NCC GOLDEN_DIR DIALECT [--blocks N] [--seed S]
"""
import os
import random
import shlex
import subprocess
import sys
import tempfile

RUN_ONLY = {"--trace-format": 1, "--trace": 1, "--max-steps": 1, "--start-block": 1, "-o": 1,
            "--block-skip": 0, "--optional-stop": 0, "--trace-blocks": 0}


def golden_cases(golden_dir):
    """(name, ARGS) of each golden case `$ ncc CMD ARGS` that reads a source program,
    without the options only a run takes."""
    for name in sorted(os.listdir(golden_dir)):
        if not name.endswith(".out"):
            continue
        with open(os.path.join(golden_dir, name), encoding="utf-8") as f:
            command = f.readline().strip()
        if not command.startswith("$ ncc ") or len(shlex.split(command)) < 4 or "@GEN@" in command:
            continue  # @GEN@: a generated hostile input (run_golden.cmake), for its diagnostics only
        words = shlex.split(command)[3:]
        args, i = [], 0
        while i < len(words):
            if words[i] in RUN_ONLY:
                i += 1 + RUN_ONLY[words[i]]
                continue
            args.append(words[i])
            i += 1
        if any(a.endswith((".nc", ".ngc", ".pp", ".txt", ".tap")) for a in args):
            yield name, args  # not a bytecode file, not without a program


def both(ncc, args, cwd):
    results = []
    for extra in ([], ["--no-fast-path"]):
        p = subprocess.run([ncc] + args[:1] + extra + args[1:], cwd=cwd, capture_output=True, text=True)
        results.append((p.returncode, p.stdout, p.stderr))
    return results


def print_first_difference(a, b, a_name, b_name):
    """The first line where two outputs differ, each under its name."""
    a, b = a.splitlines(), b.splitlines()
    for k in range(max(len(a), len(b))):
        la, lb = a[k] if k < len(a) else "<none>", b[k] if k < len(b) else "<none>"
        if la != lb:
            width = max(len(a_name), len(b_name)) + 1
            print(f"  line {k + 1}\n    {(a_name + ':').ljust(width)} {la}\n    {(b_name + ':').ljust(width)} {lb}")
            return


def differs(name, results):
    (rc1, out1, err1), (rc2, out2, err2) = results
    if (rc1, out1, err1) == (rc2, out2, err2):
        return False
    print(f"DIFFER {name}: exit {rc1} vs {rc2}")
    print_first_difference(out1 + err1, out2 + err2, "fast", "antlr")
    return True


def random_block(rng, dialect):
    """A plain word block with varied spelling, or now and then one only the parser takes."""
    letters = "GXYZIJKFSTMDHPQRL" if dialect == "iso" else "GXYZF"
    parts = []
    if rng.random() < 0.1:
        parts.append("/")
    if rng.random() < 0.5:
        parts.append("N" + " " * rng.randint(0, 1) + str(rng.randint(0, 99999)).zfill(rng.randint(1, 5)))
    for _ in range(rng.randint(0, 6)):
        letter = rng.choice(letters)
        sign = rng.choice(["", "", "-", "+"])
        kind = rng.randint(0, 4)
        if letter in "GM":
            number = str(rng.choice([0, 1, 2, 3, 17, 90, 91, 94, 54, 5, 8, 9]))
            sign = ""
        elif kind == 0:
            number = str(rng.randint(0, 9999))
        elif kind == 1:
            number = f"{rng.randint(0, 999)}.{rng.randint(0, 999)}"
        elif kind == 2:
            number = f"{rng.randint(0, 99)}."
        elif kind == 3:
            number = f".{rng.randint(0, 999)}"
        else:
            number = f"{rng.uniform(-500, 500):.4f}".lstrip("-")
        gap = " " * rng.randint(0, 2)
        parts.append(letter + gap + sign + number)
    text = (" " * rng.randint(0, 1)).join(parts) if rng.random() < 0.3 else " ".join(parts)
    r = rng.random()
    if r < 0.05:
        text += " (a comment)"
    elif r < 0.10 and dialect == "iso":
        text = f"#{rng.randint(1, 33)}={rng.randint(0, 9)}"       # the parser's
    elif r < 0.13:
        text += rng.choice(["X", "X-", "1.2.3", "@", "X1..2", "G1X"])  # damaged: the parser reports
    return text


def main():
    ncc, golden_dir, dialect = sys.argv[1], sys.argv[2], sys.argv[3]
    blocks = int(sys.argv[sys.argv.index("--blocks") + 1]) if "--blocks" in sys.argv else 3000
    seed = int(sys.argv[sys.argv.index("--seed") + 1]) if "--seed" in sys.argv else 1
    failures = cases = 0
    for name, args in golden_cases(golden_dir):
        cases += 1
        failures += differs(name, both(ncc, ["ir"] + args, golden_dir))
    # The generated corpus, in one file: blocks end at the end of the line.
    rng = random.Random(seed)
    header = {"iso": "", "gost": "%\n", "pp": "%1\n", "nc110": ""}[dialect]
    lines = [random_block(rng, dialect) for _ in range(blocks)]
    if dialect == "pp":
        lines = [f"N{k + 1} " + l.replace("N", "") for k, l in enumerate(lines)]
    with tempfile.NamedTemporaryFile("w", suffix=".nc", delete=False) as f:
        f.write(header + "\n".join(lines) + "\nM30\n")
        corpus = f.name
    try:
        failures += differs(f"generated corpus ({blocks} blocks, seed {seed})",
                            both(ncc, ["ir", corpus, "--dialect", dialect, "--error-limit", "0"], golden_dir))
    finally:
        os.unlink(corpus)
    print(f"{cases} golden cases and a generated corpus of {blocks} blocks: {failures} differ")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
