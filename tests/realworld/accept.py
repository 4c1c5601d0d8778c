#!/usr/bin/env python3
"""Measure ncc against real programs: verdicts.tsv says, for each file of a corpus
(../shared/realworld, SOURCES.tsv there), the dialect and machine it is written
for and whether ncc must accept it, refuse it with one named cause, or agree with
LinuxCNC's rs274. Prints one line per file that misses its verdict and a table
per source. Not a ctest: the corpus is not part of the project.

  tests/realworld/accept.py --ncc build/compiler/ncc ../shared/realworld
  tests/realworld/accept.py --ncc build/compiler/ncc --plain-iso ../shared/realworld
      (every file as `ncc check --dialect iso` with no machine: the issue's baseline)
"""
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOOLS = os.path.join(HERE, '..', 'diff', 'linuxcnc')


def run(cmd, timeout=60):
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, errors='replace',
                           timeout=timeout)
        return p.returncode, p.stdout + p.stderr
    except subprocess.TimeoutExpired:
        return 'timeout', ''


def errors(text):
    return [l for l in text.splitlines() if ': error: ' in l or ': fatal: ' in l]


def ncc_verdict(ncc, dialect, machine, path, library=False):
    """('accept' | 'refuse' | 'fails to run', first error, error count). A library
    (macros a caller runs with its arguments) is checked, not run."""
    args = ['--dialect', dialect] + (['--machine', machine] if machine != '-' else [])
    rc, out = run([ncc, 'check', path] + args)
    errs = errors(out)
    if rc != 0:
        return 'refuse', errs[0] if errs else out.strip()[:200], len(errs)
    if library:
        return 'accept', '', 0
    rc, out = run([ncc, 'run', path, '--trace', 'none'] + args)
    if rc != 0:
        errs = errors(out)
        return 'fails to run', errs[0] if errs else out.strip()[:200], len(errs)
    return 'accept', '', 0


def rs274_verdict(path):
    """rs274's verdict on a LinuxCNC program: 'accept' or 'refuse'."""
    import tempfile
    with tempfile.TemporaryDirectory() as home:
        var = os.path.join(home, 'offsets.var')
        with open(os.path.join(TOOLS, 'offsets.var')) as src, open(var, 'w') as dst:
            dst.write(src.read())
        env = dict(os.environ, HOME=home)
        try:
            p = subprocess.run(['rs274', '-g', '-t', os.path.join(TOOLS, 'tool.tbl'),
                                '-v', var, path], capture_output=True, text=True,
                               errors='replace', timeout=60, env=env,
                               stdin=subprocess.DEVNULL)
        except (subprocess.TimeoutExpired, FileNotFoundError):
            return 'unknown'
        return 'refuse' if p.returncode != 0 else 'accept'


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--ncc', required=True)
    ap.add_argument('--plain-iso', action='store_true')
    ap.add_argument('corpus')
    a = ap.parse_args()
    rows = [l.rstrip('\n').split('\t') for l in open(os.path.join(HERE, 'verdicts.tsv'))
            if l.strip() and not l.startswith('#')]
    table = {}
    for f, dialect, machine, verdict, expect, _why in rows:
        path = os.path.join(a.corpus, f)
        if not os.path.exists(path):
            continue
        source = f.split('/')[0]
        t = table.setdefault(source, {'files': 0, 'accepted': 0, 'as verdict': 0})
        t['files'] += 1
        if a.plain_iso:
            got, first, _ = ncc_verdict(a.ncc, 'iso', '-', path)
            t['accepted'] += got == 'accept'
            t['as verdict'] += got == 'accept'
            continue
        if verdict == 'rs274':
            want, expect = rs274_verdict(path), '-'
        else:
            want = 'accept' if verdict == 'library' else verdict
        got, first, count = ncc_verdict(a.ncc, dialect, machine, path, verdict == 'library')
        t['accepted'] += got == 'accept'
        ok = got == want
        if ok and want == 'refuse' and expect != '-':
            ok = expect in first and count == 1
        t['as verdict'] += ok
        if not ok:
            print(f'{f}: want {want}{" (" + expect + ")" if want == "refuse" else ""}, '
                  f'got {got}{" x" + str(count) if count > 1 else ""}: {first[:160]}')
    print(f'\n| source | files | accepted | as the verdict |\n|---|---|---|---|')
    total = {'files': 0, 'accepted': 0, 'as verdict': 0}
    for source in sorted(table):
        t = table[source]
        print(f"| {source} | {t['files']} | {t['accepted']} | {t['as verdict']} |")
        for k in total:
            total[k] += t[k]
    print(f"| all | {total['files']} | {total['accepted']} | {total['as verdict']} |")
    return 0


if __name__ == '__main__':
    sys.exit(main())
