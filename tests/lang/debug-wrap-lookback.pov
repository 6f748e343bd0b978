// debug-wrap-lookback.pov: how far back POV-Ray's #debug stream looks for a
// space when a line passes 80 columns: a space in columns 62 to 80 breaks
// the line there; one further left does not, and the line is cut after 80
// characters (a tab counts as one column). The expected output is what
// POV-Ray 3.7.0.10 prints.
#version 3.7;
#macro Line(K)
  #local S = "";
  #for (I, 1, K - 1) #local S = concat(S, "a"); #end
  #local S = concat(S, " ");
  #for (I, K + 1, 100) #local S = concat(S, "b"); #end
  #debug concat(S, "\n")
#end
#for (K, 40, 80, 7) Line(K) #end
Line(60) Line(61) Line(62) Line(63)
#debug "ab\tcd eeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeeee f\n"
#debug "one two three four five six seven eight nine ten eleven twelve"
#debug " thirteen fourteen fifteen\n"
