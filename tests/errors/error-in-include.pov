// expect: 3:20: expected an expression, found ';'
// expect-file: inc/broken.inc
// expect-also: included from error-in-include.pov:4:1
#include "inc/broken.inc"
