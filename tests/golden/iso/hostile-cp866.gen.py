# A program written on DOS: comments in CP866. One message for the whole file,
# which names the code page and the iconv that converts it.
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
text = '%\nO1000 (ДЕТАЛЬ КОРПУС)\nG90 G01 X0 Y0 F100 (ЧЕРНОВОЙ ПРОХОД)\nG01 X10 (КОНТУР)\nM30\n%\n'
(out / 'dos.nc').write_bytes(text.encode('cp866'))
