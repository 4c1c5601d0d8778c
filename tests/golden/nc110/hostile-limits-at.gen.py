# The limit of docs/limits.md "Text and nesting" an NC-110 block can reach within its
# 128 characters: parentheses and function calls nested 32 deep, read and run.
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
parens = b'E30=' + b'(' * 32 + b'1' + b')' * 32
calls = b'E31=' + b'ABS(' * 16 + b'(' * 16 + b'-2' + b')' * 32
assert len(calls) <= 128
(out / 'at.nc').write_bytes(b'\n'.join([parens, calls, b'(DIS,E30)', b'(DIS,E31)', b'']))
