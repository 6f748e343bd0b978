// expect: 5:46: uv_mapping must come first in a texture, before everything but an identifier
// POV-Ray: "No matching } in 'texture', uv_mapping found instead": it takes
// uv_mapping only first in the block.
#version 3.7;
sphere { 0, 1 texture { finish { ambient 1 } uv_mapping pigment { checker } } }
