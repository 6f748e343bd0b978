// checks the logical operators & and | with truth tables
#version 3.7;
#debug concat("(0&0)=", str((0&0), 0, 6), " (0&1)=", str((0&1), 0, 6), " (1&0)=", str((1&0), 0, 6), " (1&1)=", str((1&1), 0, 6), "\n")
#debug concat("(0|0)=", str((0|0), 0, 6), " (0|1)=", str((0|1), 0, 6), " (1|0)=", str((1|0), 0, 6), " (1|1)=", str((1|1), 0, 6), "\n")
#debug concat("(5&3)=", str((5&3), 0, 6), "\n")
#debug concat("(-2|0)=", str((-2|0), 0, 6), "\n")
#debug concat("(0.5&2)=", str((0.5&2), 0, 6), "\n")
#debug concat("(1e-12|0)=", str((1e-12|0), 0, 6), "\n")
