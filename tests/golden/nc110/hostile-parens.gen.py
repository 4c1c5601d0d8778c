# The input: E30= and 12,000 nested parentheses. It overflowed the stack
# (SIGSEGV); now the block is too long to read (NC1036), and a shorter one too deep
# (hostile-limits).
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
(out / 'p.nc').write_bytes(b'E30=' + b'(' * 12000 + b'1' + b')' * 12000 + b'\n')
