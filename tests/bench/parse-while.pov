// parse-while.pov: parse-speed benchmark: a 1,000,000-iteration #while
// loop with two #declares. Nothing is rendered.
#version 3.7;
#declare I = 0;
#declare S = 0;
#while (I < 1000000)
  #declare S = S + I;
  #declare I = I + 1;
#end
#debug concat("sum ", str(S, 0, 0), "\n")
