// checks nested and chained conditional operators
#version 3.7;
#macro Sign(X) (X < 0 ? -1 : X = 0 ? 0 : 1) #end
#debug concat(str(Sign(-5), 0, 6), " ", str(Sign(0), 0, 6), " ", str(Sign(7), 0, 6), "\n")
#debug concat(str((1 ? 0 ? 3 : 4 : 5), 0, 6), "\n")
#debug concat(str((0 ? 0 ? 3 : 4 : 5), 0, 6), "\n")
#debug concat(str((1 ? (0 ? 3 : 4) : 5), 0, 6), "\n")
#debug concat(str(((1 ? 2 : 3) + 10), 0, 6), "\n")
#debug concat(str((1 & 0 ? 7 : 8), 0, 6), "\n")
#debug concat(str((1 | 0 ? 7 : 8), 0, 6), "\n")
