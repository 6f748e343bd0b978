// checks that parameters passed as expressions (+Value, Value+0.0, Value*1.0) are not written back
#version 3.7;
#macro Inc(V) #declare V = V + 1; #end
#declare Value = 5.0;
Inc(+Value)
Inc(Value + 0.0)
Inc(Value * 1.0)
Inc((Value))
#debug concat("Value=", str(Value, 0, 6), "\n")
