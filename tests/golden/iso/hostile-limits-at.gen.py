# Each limit of docs/limits.md "Text and nesting", reached and read: #1 nests 32
# deep, holds runs of 8 signs and 256 operators, and leaves the most values waiting
# on the VM's stack a nesting can (6 a level: the operands of OR AND EQ + * and
# ATAN's first argument; 193 of the 256 the verifier allows: tests/unit/limits_test);
# the block that moves is 4096 bytes long.
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
level = b'1 OR 1 AND 1 EQ 1+1*' + b'-' * 8 + b'ATAN[1]/['  # 6 operators: OR AND EQ + * /
nested = level * 32 + b'1' + b']' * 32
expr = nested + b'+1' * (256 - 6 * 32)
move = b'G01 X#1 Y#2 F100 '
move += b'(' + b'A' * (4096 - len(move) - 2) + b')'
assert len(move) == 4096
(out / 'at.nc').write_bytes(b'#1=' + expr + b'\n#2=' + b'-' * 8 + b'5\n' + move + b'\nM30\n')
