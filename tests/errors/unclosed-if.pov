// expect: 3:1: #if is never closed by #end in its file
#declare A = 1;
#if (A)
sphere { 0, 1 }
