#!/usr/bin/env python3
"""Makes the damaged bytecode files diag-bc-*.bin from diag-bytecode.nc.

Run in tests/golden/gost:  python3 diag-bc-make.py /path/to/ncc
Header: "NCCB", u16 format version, u16 0, u32 section count, u32 CRC-32 (zlib)
of every byte after the 16-byte header, little-endian at offset 12; then the
sections, each a 4-byte tag, a u32 size and its bytes.
"""
import os
import re
import struct
import subprocess
import sys
import zlib

HEADER = 16
# Opcodes, numbered in the order vm/opcodes.h lists them.
# (The opcode list only: the operand kinds before it are an X-macro too.)
_HEADER_TEXT = open(os.path.join(os.path.dirname(__file__), "../../../vm/opcodes.h")).read()
OPCODES = re.findall(r"^  X\((\w+),", _HEADER_TEXT[_HEADER_TEXT.index("#define NCC_OPCODES"):], re.M)
NOP, CONST_DEC, NEG, DIV, CALL1, CODE, WORD_DEC, WORD_POP, CALL_ENTRY = (
    OPCODES.index(name) for name in ("Nop", "ConstDec", "Neg", "Div", "Call1", "Code", "WordDec", "WordPop", "CallEntry"))
SQRT = 7  # contract/builtins.h


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
    # (A changed magic is not made: such a file is read as source, see NC1009.)
    # A format version from the future (99) in bytes 4-5.
    files["version"] = good[:4] + struct.pack("<H", 99) + good[6:]
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
    # A sound file whose code divides by zero (GOST source never computes): block N1's
    # "Code G01; WordDec X 0; WordDec Y 10" (17 bytes) becomes
    # "ConstDec 10; ConstDec 0; Div; WordPop X; Nop x 2", X = 10 / 0.
    def dec(places, digits):
        return bytes([places]) + struct.pack("<i", digits)
    x, y = ord("X") - ord("A"), ord("Y") - ord("A")
    words = bytes([CODE, 0, 0, WORD_DEC, x]) + dec(0, 0) + bytes([WORD_DEC, y]) + dec(0, 10)
    divide = bytes([CONST_DEC]) + dec(0, 10) + bytes([CONST_DEC]) + dec(0, 0) + bytes([DIV, WORD_POP, x, NOP, NOP])
    assert good.count(words) == 1 and len(words) == len(divide)
    files["divide"] = with_crc(good.replace(words, divide))
    # The same bytes as "ConstDec 10; Neg; Call1 sqrt; WordPop X; Nop x 6": X = the
    # square root of -10.
    domain = bytes([CONST_DEC]) + dec(0, 10) + bytes([NEG, CALL1, SQRT, WORD_POP, x]) + bytes([NOP] * 6)
    assert len(domain) == len(words)
    files["domain"] = with_crc(good.replace(words, domain))
    # ... and as "ConstDec 10; CallEntry 0; Nop x 8": block N1 calls its own program
    # (ten times) without end.
    recurse = bytes([CONST_DEC]) + dec(0, 10) + bytes([CALL_ENTRY]) + struct.pack("<H", 0) + bytes([NOP] * 8)
    assert len(recurse) == len(words)
    files["recursion"] = with_crc(good.replace(words, recurse))

    for name, data in files.items():
        with open(f"diag-bc-{name}.bin", "wb") as f:
            f.write(data)
    os.remove("diag-bc-good.tmp")


if __name__ == "__main__":
    main()
