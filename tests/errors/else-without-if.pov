// expect: 2:1: #else without an open #if
#else
