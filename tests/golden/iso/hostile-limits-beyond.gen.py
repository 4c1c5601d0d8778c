# Each limit of docs/limits.md "Text and nesting", passed by one: 33 brackets, 33
# function calls, 9 signs in a row, 257 operators, a block of 4097 bytes. Each block
# is reported once and not read.
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
move = b'G01 X1 F100 '
move += b'(' + b'A' * (4097 - len(move) - 2) + b')'
assert len(move) == 4097
(out / 'beyond.nc').write_bytes(b'\n'.join([
    b'#1=' + b'[' * 33 + b'1' + b']' * 33,
    b'#2=' + b'ABS[' * 33 + b'1' + b']' * 33,
    b'#3=' + b'-' * 9 + b'1',
    b'#4=' + b'+'.join([b'1'] * 258),
    move,
    b'M30\n']))
