// checks identifier names: case sensitivity, digits, underscores, names close to keywords
#version 3.7;
#declare abc = 1;
#declare ABC = 2;
#declare Abc = 3;
#declare _under = 4;
#declare x2 = 5;
#declare Pi_ = 6;
#declare Version = 7;
#declare Sin = 8;
#debug concat(str(abc, 0, 0), str(ABC, 0, 0), str(Abc, 0, 0), str(_under, 0, 0), str(x2, 0, 0), str(Pi_, 0, 0), str(Version, 0, 0), str(Sin, 0, 0), "\n")
#declare A_very_long_identifier_name_of_forty_chars = 9;
#debug concat(str(A_very_long_identifier_name_of_forty_chars, 0, 0), "\n")
