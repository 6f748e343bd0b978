// expect: 3:10: 'A' is a float, not an object
#declare A = 5;
object { A }
