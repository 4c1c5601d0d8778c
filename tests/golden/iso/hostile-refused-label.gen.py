# Jumps to blocks that were refused whole: one beyond the block limit, one with a
# syntax error. Each block's own error is the one message: the jumps to their numbers
# (which were not read) add none (NC3010 would only repeat the cause).
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
