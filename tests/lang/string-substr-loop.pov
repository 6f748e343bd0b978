// checks splitting a comma-separated string with substr and converting parts with val
#version 3.7;
#declare S = "3.5,10,-2,0.25";
#declare Start = 1;
#declare Total = 0;
#for (I, 1, strlen(S) + 1)
  #if (I > strlen(S))
    #declare Total = Total + val(substr(S, Start, I - Start));
  #elseif (substr(S, I, 1) = ",")
    #declare Total = Total + val(substr(S, Start, I - Start));
    #declare Start = I + 1;
  #end
#end
#debug concat("total=", str(Total, 0, 6), "\n")
