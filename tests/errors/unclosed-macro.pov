// expect: 2:1: #macro is never closed by #end in its file
#macro M()
  sphere { 0, 1 }
