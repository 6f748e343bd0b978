// expect: 4:14: substr("abc", 4.44444e+46, 1) reaches past the end of the string (length 3)
// Found by fuzzing (UBSan): substr() converted a huge start to long before checking it.
// The range is checked on the floats now.
#declare S = substr("abc", 4.44444e+46, 1);
