// expect: 2:1: #fopen may not write "../outside.txt": scene files can only write in their own folder (lucent --io-unrestricted lifts this)
#fopen F "../outside.txt" write
