// checks declaring a float from a colour dot item (3.7 gives a float, the manual warns of a colour)
#version 3.7;
#declare MyColor = rgb <0.75, 0.5, 0.75>;
#declare RedAmt = MyColor.red;
#debug concat(str(RedAmt, 0, 6), "\n")
#declare RedAmt2 = 0.0+MyColor.red;
#declare RedAmt3 = 1.0*MyColor.green;
#declare RedAmt4 = (MyColor.blue);
#debug concat(str(RedAmt2, 0, 6), " ", str(RedAmt3, 0, 6), " ", str(RedAmt4, 0, 6), "\n")
#debug concat(str(RedAmt + 1, 0, 6), "\n")
