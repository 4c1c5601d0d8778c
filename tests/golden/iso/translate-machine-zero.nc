(translate-machine-zero: ISO's G53 moves its block in machine coordinates; pp's G53 is the machine's zero until a work offset is selected again, so into pp the block is G53, the move, and G54 again. Expected with the simulator's G54 at X-125 Y-125 Z0, in program coordinates: to 10,10,5; machine X0 Z0, which is X125 Z0; then X20)
G21 G90 G54
G00 X10 Y10 Z5
G00 G53 X0 Z0
G00 X20
M30
