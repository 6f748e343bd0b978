// expect: 3:1: #fopen may not write "/tmp/lucent-fuzz-test.txt": scene files can only write in their own folder (lucent --io-unrestricted lifts this)
// The file rule: writing only in the scene's folder (an absolute path there would do).
#fopen F "/tmp/lucent-fuzz-test.txt" write
