"""Fails when a C++ source of ncc differs from what clang-format makes of it (.clang-format).

Usage: check_format.py ROOT [CLANG_FORMAT]. Layouts differ between clang-format releases,
so the check runs only with the major version the code was formatted with, and skips
(exit 77) with another or none.
"""
import pathlib
import re
import shutil
import subprocess
import sys

VERSION = 14  # Debian 12's clang-format


def main():
    root = pathlib.Path(sys.argv[1])
    tool = sys.argv[2] if len(sys.argv) > 2 else (shutil.which(f"clang-format-{VERSION}") or shutil.which("clang-format"))
    if not tool:
        print("format: skipped, clang-format is not installed")
        return 77
    version = subprocess.run([tool, "--version"], capture_output=True, text=True).stdout
    major = re.search(r"version (\d+)", version)
    if not major or int(major.group(1)) != VERSION:
        print(f"format: skipped, {tool} is not clang-format {VERSION}: {version.strip()}")
        return 77
    # Every folder but build trees (build, build-sanitize, ...) and hidden ones.
    folders = [d for d in root.iterdir() if d.is_dir() and not d.name.startswith(("build", "."))]
    files = sorted(str(p) for folder in folders for p in folder.rglob("*")
                   if p.suffix in (".h", ".cpp") and p.is_file())
    result = subprocess.run([tool, "--dry-run", "--Werror", "--style=file", *files], capture_output=True, text=True)
    if result.returncode:
        sys.stdout.write(result.stderr)
        print(f"format: run `clang-format -i` on the files above ({len(files)} checked)")
        return 1
    print(f"format: {len(files)} files as .clang-format says")
    return 0


if __name__ == "__main__":
    sys.exit(main())
