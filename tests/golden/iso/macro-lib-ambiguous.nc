(Two files of the library start with O5000: the call cannot choose, decision 72)
G90G0X0Y0Z0
M98P5000
M98P5001
M30
