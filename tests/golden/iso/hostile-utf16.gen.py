# A program saved as UTF-16 (a Windows editor's "Unicode"): one message, which names
# UTF-16.
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
(out / 'u16.nc').write_bytes(b'\xFF\xFE' + 'G01 X1 F100\r\nM30\r\n'.encode('utf-16-le'))
