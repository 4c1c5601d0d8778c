# The input: #1= and 7,000 nested brackets. It overflowed the stack; now the
# block is too long to read (NC1036), and a shorter one too deep (hostile-limits).
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
(out / 'b.nc').write_bytes(b'#1=' + b'[' * 7000 + b'1' + b']' * 7000 + b'\nM30\n')
