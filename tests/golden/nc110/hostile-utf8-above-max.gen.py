# The 17 bytes: an F4 90 80 80 sequence (U+110000, above U+10FFFF) in a word.
# It aborted ncc (std::range_error from ANTLR's input); now the file is refused
# once, at its first bad byte (NC1035).
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
(out / 'x.nc').write_bytes(b'G1 X\xF4\x90\x80\x800 Y0\nM30\n')
