# A block of 4096 bytes (the comment lines that follow it included: a block runs
# to the next N) is read; one of 4097 is not (NC1036), and nothing else is said of it.
import pathlib
import sys

out = pathlib.Path(sys.argv[1])


def block(number, length):
    text = b'N%d G00 X1\n' % number
    while len(text) < length:
        line = min(80, length - len(text) - 1)  # the pp line limit (§2.2.1 f), then '\n'
        text += (b'"' + b'A' * (line - 2) + b'"' if line >= 2 else b' ' * line) + b'\n'
    assert len(text) == length
    return text


(out / 'b.pp').write_bytes(b'%1\n' + block(1, 4096) + block(2, 4097) + b'N9 M30\n')
