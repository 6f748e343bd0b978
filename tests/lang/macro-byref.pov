// checks by-reference parameters: #declare on a parameter passed as a lone identifier writes back
#version 3.7;
#macro Inc(V) #declare V = V + 1; #end
#declare Value = 5.0;
Inc(Value)
#debug concat("Value=", str(Value, 0, 6), "\n")
Inc(Value) Inc(Value)
#debug concat("Value=", str(Value, 0, 6), "\n")
