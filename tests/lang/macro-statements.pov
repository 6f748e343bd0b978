// checks a macro that produces statements (declarations) rather than a value
#version 3.7;
#macro Set_Pair(Name_A, Name_B)
  #declare First = Name_A;
  #declare Second = Name_B;
#end
Set_Pair(10, 20)
#debug concat(str(First, 0, 0), " ", str(Second, 0, 0), "\n")
#macro Make_Frame(OuterWidth, OuterHeight, InnerWidth, InnerHeight, Depth)
  #local Horz = (OuterHeight-InnerHeight)/2;
  #local Vert = (OuterWidth-InnerWidth)/2;
  difference {
    box { <0,0,0>, <OuterWidth,OuterHeight,Depth> }
    box { <Vert,Horz,-0.1>, <OuterWidth-Vert,OuterHeight-Horz,Depth+0.1> }
  }
#end
#declare BigFrame = object { Make_Frame(8,10,7,9,1) }
#debug concat(vstr(3, max_extent(BigFrame), ",", 0, 6), "\n")
