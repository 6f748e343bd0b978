// checks #declare deprecated (a warning on use; the value still works)
#version 3.7;
#declare deprecated Old_Value = 5;
#declare deprecated once Old_Twice = 6;
#declare deprecated "use New_Value instead" Old_Msg = 7;
#debug concat(str(Old_Value + Old_Twice + Old_Msg, 0, 0), "\n")
#debug concat(str(Old_Twice * 2, 0, 0), "\n")
