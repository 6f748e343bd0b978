// checks vectors built from vector expressions and identifiers
#version 3.7;
#declare Here = <1,2,3>;
#declare There = <3,4,5>;
#declare Foo = 2; #declare Bar = 3; #declare Bob = 9;
#declare Jump = <Foo*2,Bar-1,Bob/3>;
#declare Route = There-Here;
#declare Jump = Jump+<1,2,3>;
#debug concat(vstr(3, Route, ",", 0, 6), "\n")
#debug concat(vstr(3, Jump, ",", 0, 6), "\n")
#debug concat(vstr(3, (Here+There)/2, ",", 0, 6), "\n")
#debug concat(vstr(3, <Here.x, There.y, Here.z+There.z>, ",", 0, 6), "\n")
