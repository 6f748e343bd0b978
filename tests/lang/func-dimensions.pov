// checks dimensions() and dimension_size() on arrays of 1 to 4 dimensions
#version 3.7;
#declare A1 = array[7];
#declare A2 = array[6][10];
#declare A3 = array[2][3][4];
#declare A4 = array[1][2][3][5];
#debug concat(str(dimensions(A1), 0, 0), " ", str(dimension_size(A1, 1), 0, 0), "\n")
#debug concat(str(dimensions(A2), 0, 0), " ", str(dimension_size(A2, 1), 0, 0), " ", str(dimension_size(A2, 2), 0, 0), "\n")
#debug concat(str(dimensions(A3), 0, 0), " ", str(dimension_size(A3, 1), 0, 0), " ", str(dimension_size(A3, 2), 0, 0), " ", str(dimension_size(A3, 3), 0, 0), "\n")
#debug concat(str(dimensions(A4), 0, 0), " ", str(dimension_size(A4, 4), 0, 0), "\n")
