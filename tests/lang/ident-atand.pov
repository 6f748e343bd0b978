// checks that atand is an ordinary identifier in POV-Ray 3.7 (math.inc declares it)
#version 3.7;
#declare atand = function(X) { degrees(atan(X)) }
#debug concat(str(atand(1), 0, 3), "\n")
