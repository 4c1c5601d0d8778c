# A 10 MiB line: reported as longer than 128 characters and then parsed anyway (23 s,
# 3.8 GB). Now it is not read (NC1036).
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
line = (b'G1 X1 Y2 Z3 ' * 1000000)[: 10 * 1024 * 1024 - 1] + b'\n'
(out / 'long.nc').write_bytes(line)
