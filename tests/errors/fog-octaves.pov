// expect: 3:53: octaves must be from 0 to 1000, not -1
#version 3.7;
fog { distance 5 color rgb 1 turbulence 0.5 octaves -1 }
