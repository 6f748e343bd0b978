// expect: 5:43: uv_mapping must come first in a pigment, before everything but an identifier
// POV-Ray: "No matching } in 'pigment', uv_mapping found instead": it takes
// uv_mapping only first in the block (or after its identifier).
#version 3.7;
sphere { 0, 1 pigment { checker scale 0.1 uv_mapping } }
