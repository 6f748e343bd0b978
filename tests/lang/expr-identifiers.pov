// checks float identifiers in expressions and redeclaration using the old value
#version 3.7;
#declare Count = 0;
#declare Rows = 5.3;
#declare Cols = 6.15;
#declare Number = Rows*Cols;
#declare Count = Count+1;
#declare Count = Count+1;
#debug concat("Number=", str(Number, 0, 6), "\n")
#debug concat("Count=", str(Count, 0, 6), "\n")
#declare Offset = 11;
#declare Res = (Offset-5)/2;
#debug concat("Res=", str(Res, 0, 6), "\n")
#declare a_long_Identifier_name_123 = 42;
#debug concat(str(a_long_Identifier_name_123, 0, 6), "\n")
#declare CaseSens = 1;
#declare casesens = 2;
#debug concat(str(CaseSens, 0, 6), " ", str(casesens, 0, 6), "\n")
