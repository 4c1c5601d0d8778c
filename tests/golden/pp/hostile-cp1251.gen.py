# A program whose comments are in CP1251 (Windows Cyrillic): one message, which
# names the code page and the iconv that converts it.
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
text = '%1 "ДЕТАЛЬ ФЛАНЕЦ"\nN1 G00 X0 Y0 "ПОДВОД К ЗАГОТОВКЕ"\nN2 G01 X10 F100 "ЧИСТОВОЙ ПРОХОД"\nN3 M30\n'
(out / 'win.pp').write_bytes(text.encode('cp1251'))
