# Jumps to blocks that were not read: one beyond the block limit, one with a syntax
# error. Each block's own error is the one message: a unit with a block refused whole
# reports no jump to a number it lacks (the refused block may hold it).
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
move = b'N100 G01 X1 F100 '
move += b'(' + b'A' * (4097 - len(move) - 2) + b')'
assert len(move) == 4097
(out / 'refused.nc').write_bytes(b'\n'.join([
    b'GOTO100',
    b'GOTO200',
    move,
    b'N200 G01 X[1 Y2',
    b'M30\n']))
