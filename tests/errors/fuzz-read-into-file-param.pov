// expect: 5:23: #read cannot read into 'X': it is a file identifier
// As fuzz-read-into-file.pov, through a macro parameter that names the file
// (found by fuzzing: a use after free).
#fopen F "inc/one.txt" read
#macro M(X) #read (F, X) #end
M(F)
