# The input: X, 309 nines and =9 (the number of a system variable's name). It
# aborted ncc (std::out_of_range from stod); now NC1040 (and NC1022: the block is
# longer than 128 characters).
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
(out / 'x.nc').write_bytes(b'X' + b'9' * 309 + b'=9')
