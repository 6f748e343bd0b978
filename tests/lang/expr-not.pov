// checks the logical not operator on various values
#version 3.7;
#debug concat("!0=", str(!0, 0, 6), "\n")
#debug concat("!1=", str(!1, 0, 6), "\n")
#debug concat("!5=", str(!5, 0, 6), "\n")
#debug concat("!-2=", str(!-2, 0, 6), "\n")
#debug concat("!!7=", str(!!7, 0, 6), "\n")
#debug concat("!0+!5=", str(!0+!5, 0, 6), "\n")
#debug concat("2*!0=", str(2*!0, 0, 6), "\n")
#debug concat("!0.5=", str(!0.5, 0, 6), "\n")
#debug concat("!(1-1)=", str(!(1-1), 0, 6), "\n")
