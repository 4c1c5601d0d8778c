# The input: #1= and 50,000 minus signs. It overflowed the stack; now NC1036.
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
(out / 'neg.nc').write_bytes(b'#1=' + b'-' * 50000 + b'1\nM30\n')
