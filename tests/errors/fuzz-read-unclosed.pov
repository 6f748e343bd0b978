// expect: 6:1: expected ')' to close #read, found end of file
// Found by fuzzing (a hang): #read that reaches the end of its file skipped its
// remaining arguments up to the ')' and spun forever when the scene ended first.
#fopen F "inc/one.txt" read
#read (F, A, B
