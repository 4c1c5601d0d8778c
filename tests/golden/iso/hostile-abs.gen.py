# The input: #1= and 3,200 nested ABS[. It overflowed the stack; now NC1036.
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
(out / 'abs.nc').write_bytes(b'#1=' + b'ABS[' * 3200 + b'1' + b']' * 3200 + b'\nM30\n')
