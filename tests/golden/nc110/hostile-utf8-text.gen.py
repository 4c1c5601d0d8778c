# The bytes: F7 BF BF BF (no UTF-8 lead byte) inside a DIS text. It aborted
# ncc (std::range_error); now NC1035.
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
(out / 'dis.nc').write_bytes(b'(DIS,"\xF7\xBF\xBF\xBF")')
