// expect: 3:24: the facets pattern can only be used in a normal, not in a pigment
#version 3.7;
#declare P = pigment { facets }
