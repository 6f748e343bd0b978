// checks a combined expression using every operator class at once
#version 3.7;
#declare This = 3;
#declare That = 4;
#declare Other = 5;
#declare Thing = 5;
#declare Foo = 100;
#declare Bar = 200;
#debug concat(str(((This<That) & (Other>=Thing)?Foo:Bar), 0, 6), "\n")
#debug concat(str(((This>That) | (Other>Thing)?Foo:Bar), 0, 6), "\n")
#debug concat(str(This/That+Other*Thing, 0, 6), "\n")
#debug concat(str(-This*-That+!Other, 0, 6), "\n")
#debug concat(str((1+2*3 > 2*3+0.5 ? -This : +That) * 2, 0, 6), "\n")
