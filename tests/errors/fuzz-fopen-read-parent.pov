// expect: 3:1: #fopen may not read "../lib.sh": scene files can only read their own folder, the +L library paths and the stdlib (lucent --io-unrestricted lifts this)
// The file rule holds for #fopen ... read as for #include.
#fopen F "../lib.sh" read
