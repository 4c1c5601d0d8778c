# A program CLS calls twice, in KOI8-R: the file is refused once (NC1035), each call
# has an error, and nothing else is said of it.
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
(out / 'MP0').mkdir()
(out / 'main.nc').write_text('(CLS,P800)\nG01 X1 F100\n(CLS,P800)\nM30\n')
(out / 'MP0' / 'P800.nc').write_bytes('(DIS,"ПЕРЕХОД 2: ЧИСТОВАЯ ОБРАБОТКА")\nG1 X1 F100\n(RET)\n'.encode('koi8_r'))
