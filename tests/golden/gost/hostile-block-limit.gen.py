# A block of 4096 bytes (its comment included) is read; one of 4097 is not (NC1036),
# and nothing else is said of it.
import pathlib
import sys

out = pathlib.Path(sys.argv[1])


def block(number, length):
    text = b'N%d G00 X1. ' % number
    return text + b'(' + b'A' * (length - len(text) - 2) + b')'


(out / 'b.nc').write_bytes(b'%\n' + block(1, 4096) + b'\n' + block(2, 4097) + b'\nN9 M30\n')
