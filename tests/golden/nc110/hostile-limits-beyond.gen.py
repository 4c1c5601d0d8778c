# The limits of docs/limits.md "Text and nesting" passed by one in NC-110 blocks: 33
# parentheses, 9 signs, 257 operators (the block is also longer than 128 characters:
# NC1022). A line of 4096 bytes is only longer than a block (NC1022), one of 4097 is
# not read (NC1036 alone).
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
def line(length):
    text = b'E33=1+1'
    return text + b' ' * (length - len(text))
(out / 'beyond.nc').write_bytes(b'\n'.join([
    b'E30=' + b'(' * 33 + b'1' + b')' * 33,
    b'E31=' + b'-' * 9 + b'1',
    b'E32=' + b'+'.join([b'1'] * 258),
    line(4096),
    line(4097),
    b'']))
