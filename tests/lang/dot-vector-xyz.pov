// checks .x .y .z on a vector identifier
#version 3.7;
#declare Spot = <1.5, -2.5, 3.25>;
#debug concat(str(Spot.x, 0, 6), " ", str(Spot.y, 0, 6), " ", str(Spot.z, 0, 6), "\n")
#debug concat(str(Spot.x + Spot.y * Spot.z, 0, 6), "\n")
#debug concat(str(-Spot.x, 0, 6), "\n")
