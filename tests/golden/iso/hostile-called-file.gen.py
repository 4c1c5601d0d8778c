# A called program in CP1251: the file is refused once (NC1035), the call has an
# error, and nothing else is said of it.
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
(out / 'lib').mkdir()
(out / 'main.nc').write_text('G01 X0 F100\nM98 P2100\nM30\n')
(out / 'lib' / 'O2100.nc').write_bytes('O2100 (ОТВЕРСТИЕ ПОД РЕЗЬБУ М12, ЧИСТОВОЙ ПРОХОД)\nG01 X1\nM99\n'.encode('cp1251'))
