// expect: 2:1: cannot find include file "no-such-file.inc"
#include "no-such-file.inc"
