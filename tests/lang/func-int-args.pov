// checks functions whose integer arguments are truncated (chr, substr, dimension_size, seed)
#version 3.7;
#declare A = array[3][5];
#debug concat(str(dimension_size(A, 2.9), 0, 0), " ", chr(66.99), " ", substr("abcdef", 2.5, 3.5), "\n")
