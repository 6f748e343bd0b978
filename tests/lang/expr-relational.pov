// checks the six relational operators on floats
#version 3.7;
#macro Show(Name, V) #debug concat(Name, "=", str(V, 0, 6), "\n") #end
Show("1<2", (1<2))
Show("2<1", (2<1))
Show("2<2", (2<2))
Show("1<=2", (1<=2))
Show("2<=2", (2<=2))
Show("3<=2", (3<=2))
Show("1=1", (1=1))
Show("1=2", (1=2))
Show("1!=2", (1!=2))
Show("1!=1", (1!=1))
Show("2>=2", (2>=2))
Show("1>=2", (1>=2))
Show("3>2", (3>2))
Show("2>2", (2>2))
Show("-1<0", (-1<0))
