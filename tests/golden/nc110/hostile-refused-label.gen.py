# Jumps to blocks that were refused whole: one beyond the block limit, one nested
# beyond the limit. Each block's own error is the one message: the jumps to their
# labels (which were not read) add none (NC3010 would only repeat the cause).
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
move = b'LONG: G01 X1 F100 '
move += b'X1 ' * ((4097 - len(move)) // 3)
move += b'X' * (4097 - len(move))
assert len(move) == 4097
(out / 'refused.nc').write_bytes(b'\n'.join([
    b'(BNC,LONG)',
    b'(BNC,DEEP)',
    move,
    b'DEEP: E30=' + b'(' * 33 + b'1' + b')' * 33,
    b'M30\n']))
