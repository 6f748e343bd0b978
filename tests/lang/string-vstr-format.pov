// checks vstr() applying str()'s L and P rules to every component
#version 3.7;
#debug concat("<", vstr(3, <1,-2,3.5>, ",", 6, 2), ">\n")
#debug concat("<", vstr(3, <1,-2,3.5>, ",", -6, 2), ">\n")
#debug concat("<", vstr(3, <1.23456789,2,3>, ",", 0, -1), ">\n")
#debug concat("<", vstr(2, <0.5,1.5>, ";", 0, 0), ">\n")
#debug concat("<", vstr(3, <10,200,3000>, "", 5, 0), ">\n")
