// expect: 5:39: #read cannot read into 'F': it is a file identifier
// Found by fuzzing (ASan: heap-use-after-free): reading into the file's own
// identifier freed the file being read. POV-Ray 3.7 refuses it too ("Expected
// 'undeclared identifier', file identifier found instead").
#fopen F "inc/one.txt" read #read (F, F)
