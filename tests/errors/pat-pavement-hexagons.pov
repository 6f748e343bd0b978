// expect: 4:69: a pavement of hexagons has 1 to 5 tiles, not 6
// POV-Ray: "number_of_tiles of pavement must be between 1 and 5."
#version 3.7;
plane { y, 0 pigment { pavement number_of_sides 6 number_of_tiles 6 } }
