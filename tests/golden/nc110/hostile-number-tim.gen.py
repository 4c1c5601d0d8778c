# The input: E1=TIM and a number of 309 digits. It aborted ncc (stod); now
# NC1040 (and NC1022).
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
(out / 'tim.nc').write_bytes(b'E1=TIM' + b'9' * 309)
