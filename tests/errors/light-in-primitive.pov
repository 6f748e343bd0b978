// A light_source may be in a CSG's body, not in a primitive's (POV-Ray
// refuses it too).
// expect: 5:15: expected an object modifier or '}', found 'light_source'
#version 3.7;
sphere { 0, 1 light_source { <0,3,0>, rgb 1 } }
