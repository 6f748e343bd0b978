// expect: 2:10: expected a string, found a float
#include 42
