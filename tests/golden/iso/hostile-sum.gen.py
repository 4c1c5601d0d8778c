# The input: #1= and a sum of 80,000 terms. It overflowed the stack in the
# walks over the IR; now NC1036.
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
(out / 's.nc').write_bytes(b'#1=' + b'+'.join([b'1'] * 80000) + b'\nM30\n')
