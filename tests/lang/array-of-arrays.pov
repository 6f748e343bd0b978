// checks an array whose elements are arrays (jagged), read with double indexing
#version 3.7;
#declare Row0 = array[2] {1, 2};
#declare Row1 = array[3] {3, 4, 5};
#declare Jag = array[2] {Row0, Row1};
#debug concat(str(dimension_size(Jag[0], 1), 0, 0), " ", str(dimension_size(Jag[1], 1), 0, 0), "\n")
#declare Inner = Jag[1];
#debug concat(str(Inner[2], 0, 0), "\n")
#debug concat(str(Jag[1][2], 0, 0), " ", str(Jag[0][1], 0, 0), "\n")
