#!/usr/bin/env python3
"""Makes the damaged bytecode files diag-bc-*.bin from diag-bytecode.nc.

Run in tests/golden/gost:  python3 diag-bc-make.py /path/to/ncc
Header: "NCCB", u16 format version, u16 0, u32 section count, u32 CRC-32 (zlib)
of every byte after the 16-byte header, little-endian at offset 12; then the
sections, each a 4-byte tag, a u32 size and its bytes.
"""
import struct
import subprocess
import sys
import zlib

HEADER = 16


def with_crc(data):
    """The file with its checksum recomputed over the (changed) body."""
    return data[:12] + struct.pack("<I", zlib.crc32(data[HEADER:])) + data[HEADER:]


def section(data, tag):
    """Offset of the contents of section `tag` and its size."""
    at = HEADER
    while at < len(data):
        name, size = data[at:at + 4], struct.unpack_from("<I", data, at + 4)[0]
        if name == tag:
            return at + 8, size
        at += 8 + size
    raise SystemExit(f"no section {tag!r}")


def main():
    ncc = sys.argv[1] if len(sys.argv) > 1 else "ncc"
    subprocess.run([ncc, "compile", "diag-bytecode.nc", "-o", "diag-bc-good.tmp"], check=True)
    with open("diag-bc-good.tmp", "rb") as f:
        good = f.read()
    assert good[:4] == b"NCCB" and struct.unpack_from("<I", good, 12)[0] == zlib.crc32(good[HEADER:])

    files = {}
    # The first byte of the magic changed: not a bytecode file at all.
    files["magic"] = b"X" + good[1:]
    # Format version 2 in bytes 4-5.
    files["version"] = good[:4] + struct.pack("<H", 2) + good[6:]
    # One byte of the body flipped, the stored checksum left as it was.
    last = len(good) - 1
    files["checksum"] = good[:last] + bytes([good[last] ^ 0xFF])
    # Cut off right after the header.
    files["truncated"] = good[:HEADER]
    # The first opcode of the code changed to 0xFF, the checksum recomputed.
    code, _ = section(good, b"CODE")
    files["opcode"] = with_crc(good[:code] + b"\xff" + good[code + 1:])
    # The last four bytes cut off, the checksum recomputed: the last section is short.
    files["section"] = with_crc(good[:-4])

    for name, data in files.items():
        with open(f"diag-bc-{name}.bin", "wb") as f:
            f.write(data)
    import os
    os.remove("diag-bc-good.tmp")


if __name__ == "__main__":
    main()
