// expect: 3:30: expected a fog item or '}', found 'density'
#version 3.7;
fog { distance 5 color rgb 1 density 2 }
